// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A strict reader of PLY 1.0 files (ASCII, binary little and big endian):
// any elements, scalar and list properties of every PLY type (char .. double,
// also named int8 .. float64), read into one column per property.
//
// Strict means that every malformed input is an InputError naming the file,
// the line (ASCII) or the byte offset (binary), the element and its index,
// and what is wrong: a bad header, a count that is no number, a truncated
// file, a non-numeric token, a value out of its type's range, a negative list
// length, extra data after the last element. Tokens echoed in a message are
// cut to 60 characters, with non-printable bytes written as \xNN.
// docs/import.md says why Tessella does not use VTK's vtkPLY.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tessella::io {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };
enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

/// "char", "uchar", ... or the sized names "int8", "uint8", ...; false if unknown.
bool parsePlyType(std::string_view name, PlyType& type);
const char* plyTypeName(PlyType type);
const char* plyFormatName(PlyFormat format);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  ///< the value type (of each list item for a list)
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;  ///< the list length type (lists only)
};

struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::vector<PlyProperty> properties;
  /// The property named `name`, or nullptr.
  const PlyProperty* property(std::string_view name) const;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<std::string> comments;  ///< comment and obj_info lines, without the keyword
  std::vector<PlyElement> elements;
  std::size_t data_offset = 0;  ///< byte offset of the first data byte
  std::size_t header_lines = 0;  ///< lines of the header, end_header included
  /// The element named `name`, or nullptr.
  const PlyElement* element(std::string_view name) const;
};

/// The values of one property of one element, in element order. Every PLY
/// type fits a double exactly, so values are stored as doubles; `type` keeps
/// the declared type. A list property also has `offsets` (size count + 1):
/// the items of element i are values[offsets[i] .. offsets[i+1]).
struct PlyColumn {
  std::string name;
  PlyType type = PlyType::Float32;
  bool is_list = false;
  std::vector<double> values;
  std::vector<std::size_t> offsets;
};

/// Reads only the header of a PLY file (to tell layouts apart).
PlyHeader readPlyHeader(const std::string& path);

/// A PLY file read into memory, one column per property.
class PlyFile {
 public:
  /// Reads and checks the whole file; InputError on any malformed input.
  static PlyFile read(const std::string& path);

  const std::string& path() const { return path_; }
  const PlyHeader& header() const { return header_; }

  bool hasElement(std::string_view element) const { return header_.element(element) != nullptr; }
  bool hasProperty(std::string_view element, std::string_view property) const;
  /// Number of `element`s; InputError naming the file if there is no such element.
  std::size_t count(std::string_view element) const;
  /// The column of a property; InputError naming the file, element and
  /// property if it is missing.
  const PlyColumn& column(std::string_view element, std::string_view property) const;
  /// A scalar column; InputError if it is missing or a list.
  const PlyColumn& scalar(std::string_view element, std::string_view property) const;
  /// A list column; InputError if it is missing or a scalar.
  const PlyColumn& list(std::string_view element, std::string_view property) const;
  /// A scalar column of an integer type; InputError if it is missing, a list,
  /// or of a floating-point type.
  const PlyColumn& integerScalar(std::string_view element, std::string_view property) const;

 private:
  std::string path_;
  PlyHeader header_;
  std::vector<std::vector<PlyColumn>> columns_;  // per element, per property
};

/// A token as an error message may echo it: at most 60 characters (then
/// "..."), non-printable bytes as \xNN, in single quotes.
std::string quotedToken(std::string_view token);

}  // namespace tessella::io
