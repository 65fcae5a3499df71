// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <algorithm>
#include <bit>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "tessella/io/ply.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::io {

namespace {

struct TypeInfo {
  PlyType type;
  const char* name;
  const char* sized_name;
  std::size_t bytes;
  bool integer;
  double min, max;
};

constexpr TypeInfo kTypes[] = {
    {PlyType::Int8, "char", "int8", 1, true, -128.0, 127.0},
    {PlyType::UInt8, "uchar", "uint8", 1, true, 0.0, 255.0},
    {PlyType::Int16, "short", "int16", 2, true, -32768.0, 32767.0},
    {PlyType::UInt16, "ushort", "uint16", 2, true, 0.0, 65535.0},
    {PlyType::Int32, "int", "int32", 4, true, -2147483648.0, 2147483647.0},
    {PlyType::UInt32, "uint", "uint32", 4, true, 0.0, 4294967295.0},
    {PlyType::Float32, "float", "float32", 4, false, -double(FLT_MAX), double(FLT_MAX)},
    {PlyType::Float64, "double", "float64", 8, false, -DBL_MAX, DBL_MAX},
};

const TypeInfo& info(PlyType t) { return kTypes[static_cast<int>(t)]; }

std::string lineLabel(std::size_t line) { return "line " + std::to_string(line); }

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::vector<std::string_view> splitWords(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isBlank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !isBlank(line[i])) ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

std::string readWholeFile(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError("cannot read '" + path + "': no such file");
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError("cannot read '" + path + "': not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read '" + path + "': cannot open it");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError("cannot read '" + path + "': read error");
  return std::move(buffer).str();
}

// Parses the header from the start of `text`.
PlyHeader parseHeader(const std::string& path, std::string_view text) {
  PlyHeader h;
  auto fail = [&](std::size_t line, const std::string& what) -> InputError {
    return InputError("'" + path + "' " + lineLabel(line) + ": " + what);
  };
  std::size_t pos = 0, line_no = 0;
  bool have_format = false, ended = false;
  std::vector<std::string> element_names;
  while (pos < text.size()) {
    const std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) break;
    std::string_view line = text.substr(pos, eol - pos);
    pos = eol + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const auto words = splitWords(line);
    if (line_no == 1) {
      if (line != "ply")
        throw InputError("'" + path + "' is not a PLY file: its first line is " + quotedToken(line) +
                         ", expected 'ply'");
      continue;
    }
    if (words.empty()) throw fail(line_no, "empty header line");
    const std::string_view key = words[0];
    if (key == "comment" || key == "obj_info") {
      const std::size_t at = line.find(key) + key.size();
      std::string_view rest = line.substr(at);
      while (!rest.empty() && isBlank(rest.front())) rest.remove_prefix(1);
      h.comments.emplace_back(rest);
    } else if (key == "format") {
      if (have_format) throw fail(line_no, "a second format line");
      if (!h.elements.empty()) throw fail(line_no, "the format line must come before the elements");
      if (words.size() != 3) throw fail(line_no, "a format line is 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
      if (words[1] == "ascii")
        h.format = PlyFormat::Ascii;
      else if (words[1] == "binary_little_endian")
        h.format = PlyFormat::BinaryLittleEndian;
      else if (words[1] == "binary_big_endian")
        h.format = PlyFormat::BinaryBigEndian;
      else
        throw fail(line_no, "unknown format " + quotedToken(words[1]) +
                                " (expected ascii, binary_little_endian or binary_big_endian)");
      if (words[2] != "1.0" && words[2] != "1")
        throw fail(line_no, "unsupported PLY version " + quotedToken(words[2]) + " (expected 1.0)");
      have_format = true;
    } else if (key == "element") {
      if (!have_format) throw fail(line_no, "an element before the format line");
      if (words.size() != 3) throw fail(line_no, "an element line is 'element <name> <count>'");
      const std::string name(words[1]);
      if (std::find(element_names.begin(), element_names.end(), name) != element_names.end())
        throw fail(line_no, "element " + quotedToken(name) + " is declared twice");
      unsigned long long count = 0;
      const auto r = std::from_chars(words[2].data(), words[2].data() + words[2].size(), count);
      if (r.ec != std::errc() || r.ptr != words[2].data() + words[2].size())
        throw fail(line_no, "element " + quotedToken(name) + ": count " + quotedToken(words[2]) +
                                " is not a non-negative integer");
      element_names.push_back(name);
      h.elements.push_back(PlyElement{name, static_cast<std::size_t>(count), {}});
    } else if (key == "property") {
      if (h.elements.empty()) throw fail(line_no, "a property before any element");
      PlyElement& e = h.elements.back();
      PlyProperty p;
      // A name is the rest of the line: MorphoGraphX writes names with spaces
      // ("/Cell Axis curv10microns").
      auto restFrom = [&](std::size_t word) {
        std::string_view rest = line.substr(static_cast<std::size_t>(words[word].data() - line.data()));
        while (!rest.empty() && isBlank(rest.back())) rest.remove_suffix(1);
        return std::string(rest);
      };
      if (words.size() >= 2 && words[1] == "list") {
        if (words.size() < 5) throw fail(line_no, "a list property is 'property list <count type> <item type> <name>'");
        if (!parsePlyType(words[2], p.count_type)) throw fail(line_no, "unknown type " + quotedToken(words[2]));
        if (!info(p.count_type).integer)
          throw fail(line_no, "list length type " + quotedToken(words[2]) + " is not an integer type");
        if (!parsePlyType(words[3], p.type)) throw fail(line_no, "unknown type " + quotedToken(words[3]));
        p.is_list = true;
        p.name = restFrom(4);
      } else {
        if (words.size() < 3) throw fail(line_no, "a property line is 'property <type> <name>'");
        if (!parsePlyType(words[1], p.type)) throw fail(line_no, "unknown type " + quotedToken(words[1]));
        p.name = restFrom(2);
      }
      if (e.property(p.name))
        throw fail(line_no, "element " + quotedToken(e.name) + " declares property " + quotedToken(p.name) +
                                " twice");
      e.properties.push_back(std::move(p));
    } else if (key == "end_header") {
      if (words.size() != 1) throw fail(line_no, "text after end_header");
      ended = true;
      break;
    } else {
      throw fail(line_no, "unknown header keyword " + quotedToken(key));
    }
  }
  if (line_no == 0) throw InputError("'" + path + "' is not a PLY file: it is empty or has no complete line");
  if (!ended) throw InputError("'" + path + "': the header has no end_header line (" + std::to_string(line_no) +
                               " header lines read)");
  if (!have_format) throw InputError("'" + path + "': the header has no format line");
  for (const PlyElement& e : h.elements)
    if (e.properties.empty() && e.count > 0)
      throw InputError("'" + path + "': element " + quotedToken(e.name) + " has " + std::to_string(e.count) +
                       " entries but no property");
  h.data_offset = pos;
  h.header_lines = line_no;
  return h;
}

// --- ASCII data ---------------------------------------------------------------

class AsciiReader {
 public:
  AsciiReader(const std::string& path, std::string_view text, std::size_t first_line)
      : path_(path), text_(text), line_no_(first_line) {}

  // The next line holding any non-blank character; false at the end.
  bool nextLine(std::vector<std::string_view>& words) {
    while (pos_ < text_.size()) {
      std::size_t eol = text_.find('\n', pos_);
      if (eol == std::string_view::npos) eol = text_.size();
      const std::string_view line = text_.substr(pos_, eol - pos_);
      pos_ = std::min(eol + 1, text_.size());
      ++line_no_;
      words = splitWords(line);
      if (!words.empty()) return true;
    }
    return false;
  }
  std::size_t line() const { return line_no_; }

  InputError error(const std::string& what) const {
    return InputError("'" + path_ + "' " + lineLabel(line_no_) + ": " + what);
  }

 private:
  const std::string& path_;
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_no_;
};

// Parses one token as a value of `type`; false with `why` set when it is not one.
bool parseValue(std::string_view token, PlyType type, double& value, std::string& why) {
  const TypeInfo& t = info(type);
  std::string_view s = token;
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  const char* end = s.data() + s.size();
  if (t.integer) {
    long long v = 0;
    const auto r = std::from_chars(s.data(), end, v);
    if (r.ec == std::errc::result_out_of_range) {
      why = "is out of the range of " + std::string(t.name);
      return false;
    }
    if (r.ec != std::errc() || r.ptr != end || s.empty()) {
      why = "is not an integer (" + std::string(t.name) + ")";
      return false;
    }
    if (double(v) < t.min || double(v) > t.max) {
      why = "is out of the range of " + std::string(t.name) + " (" + std::to_string(static_cast<long long>(t.min)) +
            " .. " + std::to_string(static_cast<long long>(t.max)) + ")";
      return false;
    }
    value = double(v);
    return true;
  }
  double v = 0;
  const auto r = std::from_chars(s.data(), end, v);
  if (r.ec == std::errc::result_out_of_range) {
    why = "is out of the range of " + std::string(t.name);
    return false;
  }
  if (r.ec != std::errc() || r.ptr != end || s.empty()) {
    why = "is not a number (" + std::string(t.name) + ")";
    return false;
  }
  if (std::isfinite(v) && (v < t.min || v > t.max)) {
    why = "is out of the range of " + std::string(t.name);
    return false;
  }
  value = v;
  return true;
}

std::string elementLabel(const PlyElement& e, std::size_t i) {
  return "element " + quotedToken(e.name) + " " + std::to_string(i);
}

void readAscii(const std::string& path, const PlyHeader& h, std::string_view data,
               std::vector<std::vector<PlyColumn>>& columns) {
  AsciiReader in(path, data, h.header_lines);
  std::vector<std::string_view> words;
  std::string why;
  for (std::size_t ei = 0; ei < h.elements.size(); ++ei) {
    const PlyElement& e = h.elements[ei];
    auto& cols = columns[ei];
    for (std::size_t i = 0; i < e.count; ++i) {
      if (!in.nextLine(words))
        throw InputError("'" + path + "' is truncated: it ends at line " + std::to_string(in.line()) + " after " +
                         std::to_string(i) + " of the " + std::to_string(e.count) + " " + quotedToken(e.name) +
                         " elements");
      std::size_t w = 0;
      for (std::size_t pi = 0; pi < e.properties.size(); ++pi) {
        const PlyProperty& p = e.properties[pi];
        PlyColumn& col = cols[pi];
        auto take = [&](PlyType type, const char* what) -> double {
          if (w >= words.size())
            throw in.error(elementLabel(e, i) + " has only " + std::to_string(words.size()) +
                           " values: property " + quotedToken(p.name) + what + " is missing");
          double v = 0;
          if (!parseValue(words[w], type, v, why))
            throw in.error(elementLabel(e, i) + ", property " + quotedToken(p.name) + what + ": " +
                           quotedToken(words[w]) + " " + why);
          ++w;
          return v;
        };
        if (!p.is_list) {
          col.values.push_back(take(p.type, ""));
          continue;
        }
        const double n = take(p.count_type, " (list length)");
        if (n < 0)
          throw in.error(elementLabel(e, i) + ", property " + quotedToken(p.name) + ": negative list length " +
                         std::to_string(static_cast<long long>(n)));
        if (n > double(words.size() - w))
          throw in.error(elementLabel(e, i) + ", property " + quotedToken(p.name) + ": the list length is " +
                         std::to_string(static_cast<long long>(n)) + " but only " +
                         std::to_string(words.size() - w) + " values follow on the line");
        for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k) col.values.push_back(take(p.type, " (list item)"));
        col.offsets.push_back(col.values.size());
      }
      if (w != words.size())
        throw in.error(elementLabel(e, i) + " has " + std::to_string(words.size()) + " values, " +
                       std::to_string(words.size() - w) + " more than its properties take (next: " +
                       quotedToken(words[w]) + ")");
    }
  }
  if (in.nextLine(words))
    throw in.error("data after the last element: " + quotedToken(words[0]));
}

// --- binary data --------------------------------------------------------------

double decode(const unsigned char* p, PlyType type, bool swap) {
  unsigned char b[8];
  const std::size_t n = info(type).bytes;
  for (std::size_t k = 0; k < n; ++k) b[k] = p[swap ? n - 1 - k : k];
  switch (type) {
    case PlyType::Int8: { std::int8_t v; std::memcpy(&v, b, 1); return v; }
    case PlyType::UInt8: { std::uint8_t v; std::memcpy(&v, b, 1); return v; }
    case PlyType::Int16: { std::int16_t v; std::memcpy(&v, b, 2); return v; }
    case PlyType::UInt16: { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
    case PlyType::Int32: { std::int32_t v; std::memcpy(&v, b, 4); return v; }
    case PlyType::UInt32: { std::uint32_t v; std::memcpy(&v, b, 4); return v; }
    case PlyType::Float32: { float v; std::memcpy(&v, b, 4); return v; }
    case PlyType::Float64: { double v; std::memcpy(&v, b, 8); return v; }
  }
  return 0;
}

void readBinary(const std::string& path, const PlyHeader& h, std::string_view text,
                std::vector<std::vector<PlyColumn>>& columns) {
  const bool little = h.format == PlyFormat::BinaryLittleEndian;
  const bool swap = little != (std::endian::native == std::endian::little);
  const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
  std::size_t pos = h.data_offset;
  const std::size_t size = text.size();
  for (std::size_t ei = 0; ei < h.elements.size(); ++ei) {
    const PlyElement& e = h.elements[ei];
    // The least each entry takes: refuse an impossible count before allocating.
    std::size_t least = 0;
    for (const PlyProperty& p : e.properties) least += info(p.is_list ? p.count_type : p.type).bytes;
    if (least > 0 && e.count > (size - pos) / least)
      throw InputError("'" + path + "' is truncated: element " + quotedToken(e.name) + " declares " +
                       std::to_string(e.count) + " entries, which need at least " +
                       std::to_string(static_cast<double>(e.count) * double(least)) + " bytes, but only " +
                       std::to_string(size - pos) + " remain after byte offset " + std::to_string(pos));
    auto& cols = columns[ei];
    for (std::size_t i = 0; i < e.count; ++i) {
      for (std::size_t pi = 0; pi < e.properties.size(); ++pi) {
        const PlyProperty& p = e.properties[pi];
        PlyColumn& col = cols[pi];
        auto need = [&](std::size_t n, const char* what) {
          if (n > size - pos)
            throw InputError("'" + path + "' is truncated at byte offset " + std::to_string(pos) + ": " +
                             elementLabel(e, i) + ", property " + quotedToken(p.name) + what + " needs " +
                             std::to_string(n) + " bytes, " + std::to_string(size - pos) + " remain");
        };
        if (!p.is_list) {
          need(info(p.type).bytes, "");
          col.values.push_back(decode(bytes + pos, p.type, swap));
          pos += info(p.type).bytes;
          continue;
        }
        need(info(p.count_type).bytes, " (list length)");
        const double n = decode(bytes + pos, p.count_type, swap);
        if (n < 0)
          throw InputError("'" + path + "' byte offset " + std::to_string(pos) + ": " + elementLabel(e, i) +
                           ", property " + quotedToken(p.name) + ": negative list length " +
                           std::to_string(static_cast<long long>(n)));
        pos += info(p.count_type).bytes;
        const auto items = static_cast<std::size_t>(n);
        const std::size_t item_bytes = info(p.type).bytes;
        if (items > (size - pos) / item_bytes) need(items * item_bytes, " (list items)");
        for (std::size_t k = 0; k < items; ++k, pos += item_bytes)
          col.values.push_back(decode(bytes + pos, p.type, swap));
        col.offsets.push_back(col.values.size());
      }
    }
  }
  if (pos != size)
    throw InputError("'" + path + "' byte offset " + std::to_string(pos) + ": " + std::to_string(size - pos) +
                     " bytes of data after the last element");
}

}  // namespace

bool parsePlyType(std::string_view name, PlyType& type) {
  for (const TypeInfo& t : kTypes)
    if (name == t.name || name == t.sized_name) {
      type = t.type;
      return true;
    }
  return false;
}

const char* plyTypeName(PlyType type) { return info(type).name; }

const char* plyFormatName(PlyFormat format) {
  switch (format) {
    case PlyFormat::Ascii: return "ascii";
    case PlyFormat::BinaryLittleEndian: return "binary_little_endian";
    case PlyFormat::BinaryBigEndian: return "binary_big_endian";
  }
  return "?";
}

const PlyProperty* PlyElement::property(std::string_view n) const {
  for (const PlyProperty& p : properties)
    if (p.name == n) return &p;
  return nullptr;
}

const PlyElement* PlyHeader::element(std::string_view n) const {
  for (const PlyElement& e : elements)
    if (e.name == n) return &e;
  return nullptr;
}

std::string quotedToken(std::string_view token) {
  constexpr std::size_t kMax = 60;
  std::string out = "'";
  const std::size_t n = std::min(token.size(), kMax);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      out += static_cast<char>(c);
    } else {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (token.size() > kMax) out += "...";
  return out + "'";
}

PlyHeader readPlyHeader(const std::string& path) {
  // The header is text at the start of the file; 64 kB hold any real one.
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError("cannot read '" + path + "': no such file");
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError("cannot read '" + path + "': not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read '" + path + "': cannot open it");
  std::string text(1 << 16, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return parseHeader(path, text);
}

PlyFile PlyFile::read(const std::string& path) {
  PlyFile f;
  f.path_ = path;
  const std::string text = readWholeFile(path);
  f.header_ = parseHeader(path, text);
  f.columns_.resize(f.header_.elements.size());
  const std::size_t remaining = text.size() - f.header_.data_offset;
  for (std::size_t ei = 0; ei < f.header_.elements.size(); ++ei) {
    const PlyElement& e = f.header_.elements[ei];
    for (const PlyProperty& p : e.properties) {
      PlyColumn c{p.name, p.type, p.is_list, {}, {}};
      const std::size_t plausible = std::min(e.count, remaining / 2 + 1);  // no huge reserve for a lying count
      c.values.reserve(p.is_list ? plausible * 3 : plausible);
      if (p.is_list) {
        c.offsets.reserve(plausible + 1);
        c.offsets.push_back(0);
      }
      f.columns_[ei].push_back(std::move(c));
    }
  }
  if (f.header_.format == PlyFormat::Ascii)
    readAscii(path, f.header_, std::string_view(text).substr(f.header_.data_offset), f.columns_);
  else
    readBinary(path, f.header_, text, f.columns_);
  return f;
}

bool PlyFile::hasProperty(std::string_view element, std::string_view property) const {
  const PlyElement* e = header_.element(element);
  return e && e->property(property);
}

std::size_t PlyFile::count(std::string_view element) const {
  const PlyElement* e = header_.element(element);
  if (!e) throw InputError("'" + path_ + "' has no element " + quotedToken(element));
  return e->count;
}

const PlyColumn& PlyFile::column(std::string_view element, std::string_view property) const {
  for (std::size_t ei = 0; ei < header_.elements.size(); ++ei) {
    if (header_.elements[ei].name != element) continue;
    for (const PlyColumn& c : columns_[ei])
      if (c.name == property) return c;
    throw InputError("'" + path_ + "': element " + quotedToken(element) + " has no property " +
                     quotedToken(property));
  }
  throw InputError("'" + path_ + "' has no element " + quotedToken(element) + " (needed for property " +
                   quotedToken(property) + ")");
}

const PlyColumn& PlyFile::scalar(std::string_view element, std::string_view property) const {
  const PlyColumn& c = column(element, property);
  if (c.is_list)
    throw InputError("'" + path_ + "': property " + quotedToken(property) + " of element " + quotedToken(element) +
                     " is a list, expected a single value");
  return c;
}

const PlyColumn& PlyFile::list(std::string_view element, std::string_view property) const {
  const PlyColumn& c = column(element, property);
  if (!c.is_list)
    throw InputError("'" + path_ + "': property " + quotedToken(property) + " of element " + quotedToken(element) +
                     " is a single value, expected a list");
  return c;
}

const PlyColumn& PlyFile::integerScalar(std::string_view element, std::string_view property) const {
  const PlyColumn& c = scalar(element, property);
  if (!info(c.type).integer)
    throw InputError("'" + path_ + "': property " + quotedToken(property) + " of element " + quotedToken(element) +
                     " has type " + plyTypeName(c.type) + ", expected an integer type");
  return c;
}

}  // namespace tessella::io
