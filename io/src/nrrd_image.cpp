// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// NRRD label images: a strict parser of the header fields a label image needs, the data read by
// vtkImageReader2 (raw) or here (gzip, ASCII). See nrrd_image.hpp for why not vtkNrrdReader.

#include "nrrd_image.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <vector>

#include <vtkByteSwap.h>
#include <vtkDataArray.h>
#include <vtkImageReader2.h>
#include <vtkPointData.h>
#include <vtkType.h>
#include <vtkVariant.h>
#include <zlib.h>

#include "tessella/tissue/errors.hpp"
#include "vtk_error_capture.hpp"

namespace tessella::io::detail {

namespace {

enum class Encoding { raw, gzip, ascii };

struct NrrdType {
  int vtk_type;
  int bytes;
  bool is_signed;
};

// The NRRD type names of integers (the NRRD specification's list).
std::optional<NrrdType> integerType(const std::string& name) {
  static const std::map<std::string, NrrdType> types = {
      {"signed char", {VTK_SIGNED_CHAR, 1, true}},     {"int8", {VTK_SIGNED_CHAR, 1, true}},
      {"int8_t", {VTK_SIGNED_CHAR, 1, true}},          {"uchar", {VTK_UNSIGNED_CHAR, 1, false}},
      {"unsigned char", {VTK_UNSIGNED_CHAR, 1, false}}, {"uint8", {VTK_UNSIGNED_CHAR, 1, false}},
      {"uint8_t", {VTK_UNSIGNED_CHAR, 1, false}},      {"short", {VTK_SHORT, 2, true}},
      {"short int", {VTK_SHORT, 2, true}},             {"signed short", {VTK_SHORT, 2, true}},
      {"signed short int", {VTK_SHORT, 2, true}},      {"int16", {VTK_SHORT, 2, true}},
      {"int16_t", {VTK_SHORT, 2, true}},               {"ushort", {VTK_UNSIGNED_SHORT, 2, false}},
      {"unsigned short", {VTK_UNSIGNED_SHORT, 2, false}}, {"unsigned short int", {VTK_UNSIGNED_SHORT, 2, false}},
      {"uint16", {VTK_UNSIGNED_SHORT, 2, false}},      {"uint16_t", {VTK_UNSIGNED_SHORT, 2, false}},
      {"int", {VTK_INT, 4, true}},                     {"signed int", {VTK_INT, 4, true}},
      {"int32", {VTK_INT, 4, true}},                   {"int32_t", {VTK_INT, 4, true}},
      {"uint", {VTK_UNSIGNED_INT, 4, false}},          {"unsigned int", {VTK_UNSIGNED_INT, 4, false}},
      {"uint32", {VTK_UNSIGNED_INT, 4, false}},        {"uint32_t", {VTK_UNSIGNED_INT, 4, false}},
      {"longlong", {VTK_LONG_LONG, 8, true}},          {"long long", {VTK_LONG_LONG, 8, true}},
      {"long long int", {VTK_LONG_LONG, 8, true}},     {"signed long long", {VTK_LONG_LONG, 8, true}},
      {"signed long long int", {VTK_LONG_LONG, 8, true}}, {"int64", {VTK_LONG_LONG, 8, true}},
      {"int64_t", {VTK_LONG_LONG, 8, true}},           {"ulonglong", {VTK_UNSIGNED_LONG_LONG, 8, false}},
      {"unsigned long long", {VTK_UNSIGNED_LONG_LONG, 8, false}},
      {"unsigned long long int", {VTK_UNSIGNED_LONG_LONG, 8, false}},
      {"uint64", {VTK_UNSIGNED_LONG_LONG, 8, false}},  {"uint64_t", {VTK_UNSIGNED_LONG_LONG, 8, false}}};
  const auto it = types.find(name);
  return it == types.end() ? std::nullopt : std::optional<NrrdType>(it->second);
}

bool isFloatType(const std::string& name) { return name == "float" || name == "double"; }

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  return first == std::string::npos ? std::string() : s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  return {std::istream_iterator<std::string>(in), std::istream_iterator<std::string>()};
}

template <typename T>
std::optional<T> wholeNumber(const std::string& s) {
  T v{};
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

std::optional<double> realNumber(const std::string& s) {
  if (s == "nan" || s == "NaN" || s == "NAN") return std::numeric_limits<double>::quiet_NaN();
  return wholeNumber<double>(s);
}

// A header: the fields read (lower-case names as written), where the data starts, which file holds it.
struct NrrdHeader {
  std::map<std::string, std::string> fields;
  NrrdType type{};
  std::vector<std::int64_t> sizes;
  Encoding encoding = Encoding::raw;
  bool big_endian = false;
  std::string data_path;
  std::uintmax_t data_offset = 0;  // into data_path
  std::int64_t byte_skip = 0;      // raw only; -1: the data ends the file
  double spacing[3] = {1, 1, 1};
  double origin[3] = {0, 0, 0};
};

class HeaderParser {
 public:
  explicit HeaderParser(const std::string& path) : path_(path), file_("NRRD label image '" + path + "'") {}

  NrrdHeader parse() {
    std::ifstream in(path_, std::ios::binary);
    if (!in) fail("cannot be opened");
    std::string line;
    if (!std::getline(in, line) || line.rfind("NRRD000", 0) != 0 || line.size() < 8 ||
        !std::isdigit(static_cast<unsigned char>(line[7])))
      fail("does not start with the magic line NRRD0001..NRRD0005");
    bool blank_line = false;
    for (int n = 0; std::getline(in, line); ++n) {
      if (n > 10000) fail("has no blank line ending its header in its first 10000 lines");
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.empty()) {
        blank_line = true;
        break;
      }
      if (line[0] == '#' || line.find(":=") != std::string::npos) continue;  // comment, key/value pair
      const auto colon = line.find(": ");
      if (colon == std::string::npos) fail("header line '" + line + "' is no 'field: description'");
      std::string name = line.substr(0, colon);
      std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
      name.erase(std::remove(name.begin(), name.end(), ' '), name.end());  // "data file" = "datafile"
      if (header_.fields.count(name)) fail("has the field '" + line.substr(0, colon) + "' twice");
      header_.fields[name] = trimmed(line.substr(colon + 2));
    }
    const std::streamoff end_of_header = blank_line ? static_cast<std::streamoff>(in.tellg()) : -1;
    typeAndSizes();
    encodingAndEndian();
    dataLocation(blank_line, end_of_header);
    geometry();
    return header_;
  }

  [[noreturn]] void fail(const std::string& what) const { throw InputError(file_ + " " + what); }
  // `field` as the specification writes it ("space directions"); the fields are keyed without spaces.
  [[noreturn]] void badField(const std::string& field, const std::string& why) const {
    std::string key = field;
    key.erase(std::remove(key.begin(), key.end(), ' '), key.end());
    fail("field '" + field + "' is '" + header_.fields.at(key) + "': " + why);
  }

 private:
  const std::string* field(const std::string& name) const {
    const auto it = header_.fields.find(name);
    return it == header_.fields.end() ? nullptr : &it->second;
  }
  const std::string& required(const std::string& name) const {
    if (const std::string* value = field(name)) return *value;
    fail("has no '" + name + "' field");
  }

  void typeAndSizes() {
    const std::string& type = required("type");
    if (isFloatType(type)) badField("type", "a label image holds integers (one label per pixel), not intensities");
    if (type == "block") badField("type", "a label image holds integers, not blocks");
    const auto t = integerType(type);
    if (!t) badField("type", "no NRRD type (int8, uint8, int16, uint16, int32, uint32, int64, uint64, ...)");
    header_.type = *t;
    const auto dimension = wholeNumber<int>(required("dimension"));
    if (!dimension || *dimension < 2 || *dimension > 3)
      badField("dimension", "a label image has 2 or 3 axes");
    const std::vector<std::string> sizes = words(required("sizes"));
    if (static_cast<int>(sizes.size()) != *dimension)
      badField("sizes", std::to_string(*dimension) + " sizes expected (dimension)");
    double count = 1;
    for (const std::string& s : sizes) {
      const auto size = wholeNumber<std::int64_t>(s);
      if (!size || *size < 1 || *size > std::numeric_limits<int>::max())
        badField("sizes", "'" + s + "' is no positive size");
      header_.sizes.push_back(*size);
      count *= static_cast<double>(*size);
    }
    if (count * header_.type.bytes > 1e15) badField("sizes", "an image too large to read");
    if (const std::string* kinds = field("kinds")) {  // an axis of components (colour, vector) is no image axis
      const std::vector<std::string> k = words(*kinds);
      if (k.size() != sizes.size()) badField("kinds", std::to_string(sizes.size()) + " kinds expected (dimension)");
      for (std::size_t a = 0; a < k.size(); ++a)
        if (header_.sizes[a] > 1 && k[a] != "domain" && k[a] != "space" && k[a] != "time" && k[a] != "???" &&
            k[a] != "none")
          badField("kinds", "axis " + std::to_string(a) + " is a '" + k[a] +
                                "' axis, not an image axis: a label image has one integer per pixel");
    }
  }

  void encodingAndEndian() {
    std::string encoding = required("encoding");
    std::transform(encoding.begin(), encoding.end(), encoding.begin(), [](unsigned char c) { return std::tolower(c); });
    if (encoding == "raw") header_.encoding = Encoding::raw;
    else if (encoding == "gzip" || encoding == "gz") header_.encoding = Encoding::gzip;
    else if (encoding == "ascii" || encoding == "text" || encoding == "txt") header_.encoding = Encoding::ascii;
    else badField("encoding", "not an encoding read (raw, gzip, ascii)");
    if (const std::string* endian = field("endian")) {
      if (*endian != "little" && *endian != "big") badField("endian", "'little' or 'big' expected");
      header_.big_endian = *endian == "big";
    } else if (header_.type.bytes > 1 && header_.encoding != Encoding::ascii) {
      fail("has no 'endian' field, which " + std::to_string(header_.type.bytes) + "-byte values need");
    }
  }

  void dataLocation(bool blank_line, std::streamoff end_of_header) {
    if (const std::string* skip = field("lineskip"); skip && wholeNumber<std::int64_t>(*skip) != std::int64_t{0})
      fail("field 'line skip' is '" + *skip + "': skipping lines before the data is not supported");
    if (const std::string* skip = field("byteskip")) {
      const auto n = wholeNumber<std::int64_t>(*skip);
      if (!n || *n < -1) fail("field 'byte skip' is '" + *skip + "': a count of bytes or -1 expected");
      if (*n != 0 && header_.encoding != Encoding::raw)
        fail("field 'byte skip' is '" + *skip + "': skipping bytes is supported for raw data only");
      header_.byte_skip = *n;
    }
    if (const std::string* data_file = field("datafile")) {
      const std::vector<std::string> w = words(*data_file);
      if (w.empty() || w[0] == "LIST" || w.size() >= 4)
        fail("field 'data file' is '" + *data_file + "': data in several files is not supported; one data file");
      std::filesystem::path data(*data_file);
      if (data.is_relative()) data = std::filesystem::path(path_).parent_path() / data;
      header_.data_path = data.string();
      header_.data_offset = 0;
      if (!std::filesystem::is_regular_file(header_.data_path))
        fail("names the data file '" + header_.data_path + "', which does not exist");
    } else {
      if (!blank_line) fail("has neither a blank line ending its header (data after it) nor a 'data file' field");
      header_.data_path = path_;
      header_.data_offset = static_cast<std::uintmax_t>(end_of_header);
    }
  }

  // Pixel size from 'spacings' or the lengths of 'space directions', origin from 'space origin' (as VTK's reader).
  void geometry() {
    const std::size_t axes = header_.sizes.size();
    if (const std::string* spacings = field("spacings")) {
      const std::vector<std::string> w = words(*spacings);
      if (w.size() != axes) badField("spacings", std::to_string(axes) + " values expected (dimension)");
      for (std::size_t a = 0; a < axes; ++a) {
        const auto s = realNumber(w[a]);
        if (!s || *s == 0 || std::isinf(*s)) badField("spacings", "'" + w[a] + "' is no pixel size");
        header_.spacing[a] = std::isnan(*s) ? 1.0 : std::abs(*s);
      }
    } else if (const std::string* directions = field("spacedirections")) {
      const std::vector<std::string> w = words(*directions);
      if (w.size() != axes) badField("space directions", std::to_string(axes) + " vectors expected (dimension)");
      for (std::size_t a = 0; a < axes; ++a) {
        if (w[a] == "none") continue;
        const auto v = vector(w[a]);
        double length = 0;
        for (double x : v ? *v : std::vector<double>{}) length += x * x;
        if (!v || !(length > 0) || std::isinf(length))
          badField("space directions", "'" + w[a] + "' is no vector '(x,y,z)' of non-zero length");
        header_.spacing[a] = std::sqrt(length);
      }
    }
    if (const std::string* origin = field("spaceorigin")) {
      const auto v = vector(*origin);
      if (!v || v->size() > 3 || std::any_of(v->begin(), v->end(), [](double x) { return !std::isfinite(x); }))
        badField("space origin", "no vector '(x,y,z)' of finite numbers");
      for (std::size_t a = 0; a < v->size(); ++a) header_.origin[a] = (*v)[a];
    }
  }

  // "(x,y,z)" -> {x, y, z}.
  static std::optional<std::vector<double>> vector(const std::string& s) {
    if (s.size() < 2 || s.front() != '(' || s.back() != ')') return std::nullopt;
    std::vector<double> v;
    std::istringstream in(s.substr(1, s.size() - 2));
    for (std::string item; std::getline(in, item, ',');) {
      const auto x = realNumber(trimmed(item));
      if (!x) return std::nullopt;
      v.push_back(*x);
    }
    if (v.empty()) return std::nullopt;
    return v;
  }

  std::string path_, file_;
  NrrdHeader header_;
};

std::string describe(const NrrdHeader& h) {
  std::string s;
  for (std::int64_t size : h.sizes) s += (s.empty() ? "" : " x ") + std::to_string(size);
  return s + " values of " + std::to_string(h.type.bytes) + " byte(s)";
}

std::int64_t valueCount(const NrrdHeader& h) {
  std::int64_t n = 1;
  for (std::int64_t size : h.sizes) n *= size;
  return n;
}

vtkSmartPointer<vtkImageData> emptyImage(const NrrdHeader& h) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(static_cast<int>(h.sizes[0]), static_cast<int>(h.sizes[1]),
                       h.sizes.size() > 2 ? static_cast<int>(h.sizes[2]) : 1);
  image->SetSpacing(h.spacing);
  image->SetOrigin(h.origin);
  auto scalars = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(h.type.vtk_type));
  scalars->SetNumberOfComponents(1);
  scalars->SetNumberOfTuples(valueCount(h));
  scalars->SetName("labels");
  image->GetPointData()->SetScalars(scalars);
  return image;
}

// Raw data: VTK's vtkImageReader2 told the offset, sizes, type and byte order (rows as stored: no flip).
vtkSmartPointer<vtkImageData> readRaw(const NrrdHeader& h, const HeaderParser& parser) {
  const std::uintmax_t bytes = static_cast<std::uintmax_t>(valueCount(h)) * static_cast<std::uintmax_t>(h.type.bytes);
  const std::uintmax_t file_size = std::filesystem::file_size(h.data_path);
  std::uintmax_t start = h.data_offset + static_cast<std::uintmax_t>(std::max<std::int64_t>(h.byte_skip, 0));
  if (h.byte_skip == -1) start = file_size >= bytes ? file_size - bytes : 0;
  const std::uintmax_t found = file_size >= start ? file_size - start : 0;
  if (found != bytes)
    parser.fail("holds " + std::to_string(found) + " bytes of raw data in '" + h.data_path + "', its sizes and type (" +
                describe(h) + ") need " + std::to_string(bytes));
  auto reader = vtkSmartPointer<vtkImageReader2>::New();
  auto capture = vtkSmartPointer<VtkErrorCapture>::New();
  capture->watch(reader.GetPointer());
  reader->SetFileName(h.data_path.c_str());
  reader->SetHeaderSize(static_cast<unsigned long>(start));
  reader->SetFileDimensionality(3);
  reader->SetDataExtent(0, static_cast<int>(h.sizes[0]) - 1, 0, static_cast<int>(h.sizes[1]) - 1, 0,
                        h.sizes.size() > 2 ? static_cast<int>(h.sizes[2]) - 1 : 0);
  reader->SetDataScalarType(h.type.vtk_type);
  reader->SetNumberOfScalarComponents(1);
  if (h.big_endian) reader->SetDataByteOrderToBigEndian();
  else reader->SetDataByteOrderToLittleEndian();
  reader->FileLowerLeftOn();
  reader->SetDataSpacing(h.spacing[0], h.spacing[1], h.spacing[2]);
  reader->SetDataOrigin(h.origin[0], h.origin[1], h.origin[2]);
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  if (capture->failed() || !image || !image->GetPointData()->GetScalars())
    parser.fail("data could not be read from '" + h.data_path + "': " +
                (capture->failed() ? capture->message() : std::string("no image")));
  return image;
}

// Gzip data: inflated here (zlib; VTK's reader would take a short first axis for components).
vtkSmartPointer<vtkImageData> readGzip(const NrrdHeader& h, const HeaderParser& parser) {
  std::ifstream in(h.data_path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(h.data_offset));
  const std::string compressed{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  // Deflate expands at most ~1032 times: a header claiming more is refused before its image is allocated.
  const double most = 1032.0 * static_cast<double>(compressed.size()) + 1024;
  if (static_cast<double>(valueCount(h)) * h.type.bytes > most)
    parser.fail("holds " + std::to_string(compressed.size()) + " bytes of gzip data, too few for its sizes and type (" +
                describe(h) + ")");
  vtkSmartPointer<vtkImageData> image = emptyImage(h);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const std::size_t bytes = static_cast<std::size_t>(valueCount(h)) * static_cast<std::size_t>(h.type.bytes);
  auto* out = static_cast<unsigned char*>(scalars->GetVoidPointer(0));
  z_stream z{};
  if (inflateInit2(&z, 15 + 32) != Z_OK) parser.fail("gzip data: zlib could not start");
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
  std::size_t in_left = compressed.size(), produced = 0;
  unsigned char extra[256];  // where output beyond the sizes goes, to tell too much data from enough
  int status = Z_OK;
  while (status == Z_OK && produced <= bytes) {
    if (z.avail_in == 0 && in_left > 0) {
      z.avail_in = static_cast<uInt>(std::min<std::size_t>(in_left, 1u << 30));
      in_left -= z.avail_in;
    }
    const bool room = produced < bytes;
    z.next_out = room ? out + produced : extra;
    z.avail_out = static_cast<uInt>(room ? std::min<std::size_t>(bytes - produced, 1u << 30) : sizeof extra);
    const uInt before = z.avail_out;
    status = inflate(&z, Z_NO_FLUSH);
    produced += before - z.avail_out;
  }
  const std::string zlib_message = z.msg ? z.msg : "error " + std::to_string(status);
  inflateEnd(&z);
  // Z_BUF_ERROR: no progress possible, the data ends before the gzip stream does.
  if (status != Z_OK && status != Z_STREAM_END && status != Z_BUF_ERROR)
    parser.fail("gzip data in '" + h.data_path + "' is corrupt (zlib: " + zlib_message + ")");
  if (produced != bytes || status == Z_BUF_ERROR)
    parser.fail("holds " + std::string(produced > bytes ? "more than " : "") + std::to_string(std::min(produced, bytes)) +
                " bytes of gzip data" + (status == Z_BUF_ERROR ? " (truncated)" : "") + ", its sizes and type (" +
                describe(h) + ") need " + std::to_string(bytes));
  if (h.type.bytes > 1 && h.big_endian != (std::endian::native == std::endian::big))
    vtkByteSwap::SwapVoidRange(out, static_cast<vtkIdType>(valueCount(h)), h.type.bytes);
  return image;
}

// ASCII data: whole numbers separated by white space, each in the range of the type.
vtkSmartPointer<vtkImageData> readAscii(const NrrdHeader& h, const HeaderParser& parser) {
  std::ifstream in(h.data_path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(h.data_offset));
  const std::int64_t count = valueCount(h);
  // Every value takes a character at least: a header claiming more is refused before its image is allocated.
  const std::uintmax_t file_size = std::filesystem::file_size(h.data_path);
  const std::uintmax_t text = file_size - std::min(h.data_offset, file_size);
  if (static_cast<std::uintmax_t>(count) > text)
    parser.fail("holds " + std::to_string(text) + " bytes of ASCII data, too few for its sizes (" + describe(h) +
                ")");
  vtkSmartPointer<vtkImageData> image = emptyImage(h);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const int bits = 8 * h.type.bytes;
  std::int64_t n = 0;
  for (std::string token; in >> token; ++n) {
    if (n == count) parser.fail("holds more than the " + std::to_string(count) + " ASCII values its sizes give");
    bool ok = false;
    if (h.type.is_signed) {
      const auto v = wholeNumber<std::int64_t>(token);
      const std::int64_t limit = bits == 64 ? std::numeric_limits<std::int64_t>::max() : (std::int64_t{1} << (bits - 1)) - 1;
      ok = v && *v <= limit && *v >= -limit - 1;
      if (ok) scalars->SetVariantValue(n, vtkVariant(static_cast<long long>(*v)));
    } else {
      const auto v = wholeNumber<std::uint64_t>(token);
      ok = v && (bits == 64 || *v < (std::uint64_t{1} << bits));
      if (ok) scalars->SetVariantValue(n, vtkVariant(static_cast<unsigned long long>(*v)));
    }
    if (!ok)
      parser.fail("ASCII value " + std::to_string(n) + " is '" + token + "', no " +
                  (h.type.is_signed ? "signed " : "unsigned ") + std::to_string(bits) + "-bit integer (field 'type')");
  }
  if (n != count)
    parser.fail("holds " + std::to_string(n) + " ASCII values, its sizes (" + describe(h) + ") need " +
                std::to_string(count));
  return image;
}

}  // namespace

vtkSmartPointer<vtkImageData> readNrrdImage(const std::string& path) {
  HeaderParser parser(path);
  const NrrdHeader header = parser.parse();
  switch (header.encoding) {
    case Encoding::raw:
      return readRaw(header, parser);
    case Encoding::gzip:
      return readGzip(header, parser);
    case Encoding::ascii:
      return readAscii(header, parser);
  }
  parser.fail("has an unknown encoding");
}

}  // namespace tessella::io::detail
