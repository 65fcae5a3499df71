// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "snapshot_checksum.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <type_traits>
#include <vector>

#include <vtkAbstractArray.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVariant.h>
#include <zlib.h>
#ifdef TESSELLA_HAVE_LIBDEFLATE
#include <libdeflate.h>
#endif

#include "tessella/tissue/errors.hpp"

namespace tessella::io::detail {
namespace {

constexpr bool kLittleEndian = std::endian::native == std::endian::little;

template <typename U>
U littleEndian(U v) {
  if constexpr (kLittleEndian || sizeof(U) == 1) {
    return v;
  } else {
    U out = 0;
    for (std::size_t i = 0; i < sizeof(U); ++i) out = static_cast<U>((out << 8) | ((v >> (8 * i)) & 0xff));
    return out;
  }
}

/// The CRC-32 of zlib (and gzip, PNG): libdeflate's implementation when the
/// build found it (carry-less multiplication, several times faster), else
/// zlib's. Both give the same value for the same bytes.
class Crc32 {
 public:
  void bytes(const void* data, std::size_t n) {
    if (n == 0) return;  // (a null buffer would reset it)
#ifdef TESSELLA_HAVE_LIBDEFLATE
    crc_ = libdeflate_crc32(static_cast<std::uint32_t>(crc_), data, n);
#else
    crc_ = crc32_z(crc_, static_cast<const Bytef*>(data), n);
#endif
  }
  void word(std::uint64_t v) {
    v = littleEndian(v);
    bytes(&v, sizeof v);
  }
  std::uint32_t value() const { return static_cast<std::uint32_t>(crc_); }

 private:
  uLong crc_ = crc32_z(0L, Z_NULL, 0);
};

/// How a checksum sees an array's value type: integer, unsigned or floating
/// point, and the size, so that a file whose Int32 array became UInt32 (same
/// bytes, another property type) is told apart. VTK picks the integer width
/// of the cell arrays itself, so those are seen as "integers" only.
constexpr std::uint64_t kCanonicalIntegers = 0x100, kStrings = 0x200, kOther = 0x300;

template <typename T>
constexpr std::uint64_t typeWord() {
  return (std::is_floating_point_v<T> ? 2u : std::is_signed_v<T> ? 1u : 0u) * 16u + sizeof(T);
}

/// The values in a canonical form: floating point as its own little-endian
/// bits, every integer type as a little-endian 64-bit integer.
template <typename T>
void addValues(Crc32& crc, const T* values, std::size_t n) {
  using Word = std::conditional_t<std::is_floating_point_v<T>,
                                  std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>, std::uint64_t>;
  if constexpr (kLittleEndian && sizeof(T) == sizeof(Word)) {
    crc.bytes(values, n * sizeof(T));  // already canonical
  } else {
    Word buffer[8192];
    for (std::size_t start = 0; start < n; start += std::size(buffer)) {
      const std::size_t count = std::min(std::size(buffer), n - start);
      for (std::size_t i = 0; i < count; ++i) {
        const T v = values[start + i];
        Word w;
        if constexpr (std::is_floating_point_v<T>)
          std::memcpy(&w, &v, sizeof w);
        else if constexpr (std::is_signed_v<T>)
          w = static_cast<Word>(static_cast<std::int64_t>(v));
        else
          w = static_cast<Word>(v);
        buffer[i] = littleEndian(w);
      }
      crc.bytes(buffer, count * sizeof(Word));
    }
  }
}

template <typename T>
void addTyped(Crc32& crc, const T* values, std::size_t n, bool canonical_integers) {
  crc.word(canonical_integers && std::is_integral_v<T> ? kCanonicalIntegers : typeWord<T>());
  addValues(crc, values, n);
}

void addText(Crc32& crc, const std::string& s) {
  crc.word(s.size());
  crc.bytes(s.data(), s.size());
}

std::uint32_t checksumOf(vtkAbstractArray* array, bool canonical_integers) {
  Crc32 crc;
  crc.word(static_cast<std::uint64_t>(array->GetNumberOfTuples()));
  crc.word(static_cast<std::uint64_t>(array->GetNumberOfComponents()));
  const auto n = static_cast<std::size_t>(std::max<vtkIdType>(array->GetNumberOfValues(), 0));
  auto* data = vtkDataArray::SafeDownCast(array);
  if (auto* strings = vtkStringArray::SafeDownCast(array)) {
    crc.word(kStrings);
    for (vtkIdType i = 0; i < strings->GetNumberOfValues(); ++i) addText(crc, strings->GetValue(i));
  } else if (data && data->HasStandardMemoryLayout() && data->GetDataType() != VTK_BIT) {
    switch (data->GetDataType()) {
      vtkTemplateMacro(addTyped(crc, static_cast<const VTK_TT*>(n > 0 ? data->GetVoidPointer(0) : nullptr), n,
                                canonical_integers));
      default:
        crc.word(kOther);
        for (std::size_t i = 0; i < n; ++i) addText(crc, array->GetVariantValue(static_cast<vtkIdType>(i)).ToString());
    }
  } else {  // bit arrays, other layouts and kinds: the values as text
    crc.word(kOther);
    for (std::size_t i = 0; i < n; ++i) addText(crc, array->GetVariantValue(static_cast<vtkIdType>(i)).ToString());
  }
  return crc.value();
}

struct Keyed {
  std::string key;
  vtkAbstractArray* array;
  bool canonical_integers = false;  ///< VTK chooses its integer width (the cell arrays)
};

void addNamed(std::vector<Keyed>& out, vtkFieldData* data, const std::string& prefix) {
  if (!data) return;
  for (int i = 0; i < data->GetNumberOfArrays(); ++i) {
    vtkAbstractArray* a = data->GetAbstractArray(i);
    if (!a || !a->GetName() || !*a->GetName() || std::strcmp(a->GetName(), kChecksumArray) == 0) continue;
    out.push_back({prefix + a->GetName(), a});
  }
}

/// Every array of the grid with its key, sorted by key. The point and cell
/// arrays of a grid without points or cells are left out (VTK may or may
/// not create empty ones when it reads such a file).
std::vector<Keyed> arraysOf(vtkUnstructuredGrid* grid) {
  std::vector<Keyed> out;
  if (grid->GetNumberOfPoints() > 0) out.push_back({"points", grid->GetPoints()->GetData()});
  if (grid->GetNumberOfCells() > 0) {
    if (vtkCellArray* cells = grid->GetCells()) {
      out.push_back({"cells/offsets", cells->GetOffsetsArray(), true});
      out.push_back({"cells/connectivity", cells->GetConnectivityArray(), true});
    }
    out.push_back({"cells/types", grid->GetCellTypesArray()});
    out.push_back({"cells/faces", grid->GetFaces(), true});
    out.push_back({"cells/face_locations", grid->GetFaceLocations(), true});
  }
  addNamed(out, grid->GetPointData(), "point_data/");
  addNamed(out, grid->GetCellData(), "cell_data/");
  addNamed(out, grid->GetFieldData(), "field_data/");
  std::erase_if(out, [](const Keyed& k) { return k.array == nullptr; });
  std::stable_sort(out.begin(), out.end(), [](const Keyed& a, const Keyed& b) { return a.key < b.key; });
  return out;
}

std::string hex8(std::uint32_t v) {
  char text[9];
  std::snprintf(text, sizeof text, "%08x", v);
  return text;
}

/// At most 80 characters of `s`, non-printable bytes as '?'.
std::string printable(const std::string& s) {
  std::string out = s.substr(0, 80);
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  return out + (s.size() > 80 ? "..." : "");
}

}  // namespace

void addChecksums(vtkUnstructuredGrid* grid) {
  auto list = vtkSmartPointer<vtkStringArray>::New();
  list->SetName(kChecksumArray);
  for (const Keyed& k : arraysOf(grid)) list->InsertNextValue(hex8(checksumOf(k.array, k.canonical_integers)) + " " + k.key);
  grid->GetFieldData()->AddArray(list);
}

void verifyChecksums(vtkUnstructuredGrid* grid, const std::string& path) {
  const auto fail = [&](const std::string& problem) {
    throw InputError("'" + path + "': " + problem + "; the file is corrupted");
  };
  vtkAbstractArray* stored = grid->GetFieldData()->GetAbstractArray(kChecksumArray);
  if (!stored) return;  // an older snapshot, or another writer's file
  auto* list = vtkStringArray::SafeDownCast(stored);
  if (!list) fail(std::string("field data '") + kChecksumArray + "' is not a string array");
  const std::vector<Keyed> arrays = arraysOf(grid);
  for (vtkIdType i = 0; i < list->GetNumberOfValues(); ++i) {
    const std::string entry = list->GetValue(i);
    const bool well_formed = entry.size() > 9 && entry[8] == ' ' &&
                             std::all_of(entry.begin(), entry.begin() + 8, [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); });
    if (!well_formed)
      fail(std::string(kChecksumArray) + "[" + std::to_string(i) + "] = '" + printable(entry) +
           "' is not '<8 hex digits> <array>'");
    const std::uint32_t expected = static_cast<std::uint32_t>(std::stoul(entry.substr(0, 8), nullptr, 16));
    const std::string key = entry.substr(9);
    const auto it = std::lower_bound(arrays.begin(), arrays.end(), key,
                                     [](const Keyed& k, const std::string& name) { return k.key < name; });
    if (it == arrays.end() || it->key != key)
      fail("array '" + printable(key) + "' has a checksum but is not in the file");
    const std::uint32_t actual = checksumOf(it->array, it->canonical_integers);
    if (actual != expected)
      fail("array '" + key + "' does not match its checksum (CRC-32 " + hex8(actual) + ", written " + hex8(expected) +
           ")");
  }
}

}  // namespace tessella::io::detail
