// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "grid_transfer.hpp"

#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <algorithm>
#include <limits>
#include <string>
#include <string_view>

#include <vtkAbstractArray.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkType.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>

namespace tessella::io::detail {
namespace {

constexpr char kMagic[8] = {'T', 'S', 'G', 'R', 'I', 'D', '1', '\n'};
// What one array slot holds.
constexpr std::uint8_t kNone = 0, kData = 1, kStrings = 2;

/// Payloads from this size on sit at a page boundary of the file, after one
/// page of their own, so that the receiver maps them instead of copying.
constexpr std::size_t kMappedFrom = std::size_t{1} << 20;

std::size_t pageSize() {
  static const std::size_t page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  return page;
}

/// Buffered sequential writes to a file descriptor; large payloads go
/// straight from their memory.
class Sender {
 public:
  explicit Sender(int fd) : fd_(fd) {}
  void word(std::uint64_t v) { buffer_.append(reinterpret_cast<const char*>(&v), sizeof v); }
  void text(std::string_view s) {
    word(s.size());
    buffer_.append(s);
  }
  void bytes(const void* data, std::size_t n) {
    if (n < (std::size_t{1} << 16)) {
      buffer_.append(static_cast<const char*>(data), n);
      return;
    }
    flush();
    writeAll(data, n);
  }
  /// A payload: from kMappedFrom bytes on, its file offset (a page boundary
  /// one page or more past here), zeros up to it, then the bytes.
  void payload(const void* data, std::size_t n) {
    if (n >= kMappedFrom) {
      const std::size_t page = pageSize();
      const std::size_t at = (written_ + buffer_.size() + sizeof(std::uint64_t) + 2 * page - 1) / page * page;
      word(at);
      buffer_.append(at - written_ - buffer_.size(), '\0');
    }
    bytes(data, n);
  }
  bool finish() {
    flush();
    return ok_;
  }

 private:
  void flush() {
    writeAll(buffer_.data(), buffer_.size());
    buffer_.clear();
  }
  void writeAll(const void* data, std::size_t n) {
    const char* p = static_cast<const char*>(data);
    while (ok_ && n > 0) {
      const ssize_t w = ::write(fd_, p, n);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) {
        ok_ = false;
      } else {
        p += w, n -= static_cast<std::size_t>(w);
        written_ += static_cast<std::size_t>(w);
      }
    }
  }
  int fd_;
  bool ok_ = true;
  std::size_t written_ = 0;
  std::string buffer_;
};

bool sendArray(Sender& out, vtkAbstractArray* array) {
  if (!array) {
    out.word(kNone);
    return true;
  }
  if (auto* strings = vtkStringArray::SafeDownCast(array)) {
    out.word(kStrings);
    out.text(array->GetName() ? array->GetName() : "");
    out.word(static_cast<std::uint64_t>(strings->GetNumberOfComponents()));
    out.word(static_cast<std::uint64_t>(strings->GetNumberOfValues()));
    for (vtkIdType i = 0; i < strings->GetNumberOfValues(); ++i) out.text(strings->GetValue(i));
    return true;
  }
  auto* data = vtkDataArray::SafeDownCast(array);
  if (!data || !data->HasStandardMemoryLayout() || data->GetDataType() == VTK_BIT || data->GetNumberOfTuples() < 0 ||
      data->GetNumberOfComponents() < 1)
    return false;
  out.word(kData);
  out.text(array->GetName() ? array->GetName() : "");
  out.word(static_cast<std::uint64_t>(data->GetDataType()));
  out.word(static_cast<std::uint64_t>(data->GetDataTypeSize()));
  out.word(static_cast<std::uint64_t>(data->GetNumberOfComponents()));
  out.word(static_cast<std::uint64_t>(data->GetNumberOfTuples()));
  const std::size_t n =
      static_cast<std::size_t>(data->GetNumberOfValues()) * static_cast<std::size_t>(data->GetDataTypeSize());
  if (n > 0) out.payload(data->GetVoidPointer(0), n);
  return true;
}

bool sendFields(Sender& out, vtkFieldData* fields) {
  const int n = fields ? fields->GetNumberOfArrays() : 0;
  out.word(static_cast<std::uint64_t>(n));
  for (int i = 0; i < n; ++i) {
    vtkAbstractArray* a = fields->GetAbstractArray(i);
    if (!a || !sendArray(out, a)) return false;
  }
  return true;
}

/// Reads what Sender wrote from the file, never past its end.
class Receiver {
 public:
  Receiver(int fd, std::size_t size) : fd_(fd), size_(size) {}
  bool word(std::uint64_t& v) { return take(&v, sizeof v); }
  bool text(std::string& s) {
    std::uint64_t n = 0;
    if (!word(n) || n > left()) return false;
    s.resize(static_cast<std::size_t>(n));
    return take(s.data(), s.size());
  }
  bool take(void* to, std::size_t n) {
    if (n > left()) return false;
    char* out = static_cast<char*>(to);
    while (n > 0) {
      if (at_ == buffer_.size() && !fill()) return false;
      const std::size_t k = std::min(n, buffer_.size() - at_);
      std::memcpy(out, buffer_.data() + at_, k);
      at_ += k, position_ += k, out += k, n -= k;
    }
    return true;
  }
  /// A payload of n bytes into `array` (n values of its type): mapped when
  /// Sender placed it on its own pages, else copied.
  bool payload(vtkDataArray* array, std::size_t values, std::size_t n) {
    if (n < kMappedFrom) {
      array->SetNumberOfValues(static_cast<vtkIdType>(values));
      return take(array->GetVoidPointer(0), n);
    }
    const std::size_t page = pageSize();
    std::uint64_t at = 0;
    if (!word(at) || at % page != 0 || at < position_ + page || at - position_ > 2 * page || at > size_ ||
        n > size_ - at)
      return false;
    void* base = ::mmap(nullptr, page + n, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd_, static_cast<off_t>(at - page));
    if (base == MAP_FAILED) return false;
    // Readable and writable as any array; a write copies the page it touches.
    if (::mprotect(base, page + n, PROT_READ | PROT_WRITE) != 0) {
      ::munmap(base, page + n);
      return false;
    }
    *static_cast<std::size_t*>(base) = page + n;  // for unmapPayload
    array->SetVoidArray(static_cast<char*>(base) + page, static_cast<vtkIdType>(values), 0,
                        vtkAbstractArray::VTK_DATA_ARRAY_USER_DEFINED);
    array->SetArrayFreeFunction(&unmapPayload);
    position_ = at + n;
    buffer_.clear();
    at_ = 0;
    return true;
  }
  std::size_t left() const { return size_ - position_; }

 private:
  /// VTK's free function of a mapped payload: the mapping starts one page
  /// before the values, with its length in its first word.
  static void unmapPayload(void* values) {
    char* base = static_cast<char*>(values) - pageSize();
    ::munmap(base, *reinterpret_cast<std::size_t*>(base));
  }
  bool fill() {
    buffer_.resize(std::min<std::size_t>(std::size_t{1} << 16, left()));
    std::size_t got = 0;
    while (got < buffer_.size()) {
      const ssize_t r = ::pread(fd_, buffer_.data() + got, buffer_.size() - got, static_cast<off_t>(position_ + got));
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) return false;
      got += static_cast<std::size_t>(r);
    }
    at_ = 0;
    return !buffer_.empty();
  }
  int fd_;
  std::size_t size_;
  std::size_t position_ = 0;  // in the file
  std::string buffer_;        // the file from position_ - at_ on
  std::size_t at_ = 0;
};

/// One array as sendArray wrote it: `ok` false when the bytes make no sense.
struct Received {
  bool ok = false;
  vtkSmartPointer<vtkAbstractArray> array;  // null for an empty slot
};

/// A data array of the class the grid's structure wants for slot `role`
/// (none: VTK's class for the value type), when the sizes fit.
enum class Role { Any, CellIds, Types, Ids };

bool floating(int type) { return type == VTK_FLOAT || type == VTK_DOUBLE; }

vtkSmartPointer<vtkDataArray> newArray(int type, std::uint64_t size, Role role) {
  vtkSmartPointer<vtkDataArray> data;
  if (role == Role::CellIds && size == 8) data = vtkSmartPointer<vtkTypeInt64Array>::New();
  else if (role == Role::CellIds && size == 4) data = vtkSmartPointer<vtkTypeInt32Array>::New();
  else if (role == Role::Types) data = vtkSmartPointer<vtkUnsignedCharArray>::New();
  else if (role == Role::Ids) data = vtkSmartPointer<vtkIdTypeArray>::New();
  if (data && (static_cast<std::uint64_t>(data->GetDataTypeSize()) != size ||
               floating(data->GetDataType()) != floating(type)))
    data = nullptr;  // as<> below refuses it
  if (!data) data.TakeReference(vtkDataArray::CreateDataArray(type));
  return data;
}

Received receiveArray(Receiver& in, Role role = Role::Any) {
  std::uint64_t kind = 0;
  if (!in.word(kind)) return {};
  if (kind == kNone) return {true, nullptr};
  std::string name;
  if (!in.text(name)) return {};
  if (kind == kStrings) {
    std::uint64_t components = 0, count = 0;
    // each value takes at least its length word
    if (!in.word(components) || !in.word(count) || components < 1 || components > (1u << 16) ||
        count > in.left() / sizeof(std::uint64_t) || count % components != 0)
      return {};
    auto strings = vtkSmartPointer<vtkStringArray>::New();
    strings->SetNumberOfComponents(static_cast<int>(components));
    strings->SetNumberOfValues(static_cast<vtkIdType>(count));
    std::string value;
    for (std::uint64_t i = 0; i < count; ++i) {
      if (!in.text(value)) return {};
      strings->SetValue(static_cast<vtkIdType>(i), value);
    }
    if (!name.empty()) strings->SetName(name.c_str());
    return {true, strings};
  }
  std::uint64_t type = 0, size = 0, components = 0, tuples = 0;
  if (kind != kData || !in.word(type) || !in.word(size) || !in.word(components) || !in.word(tuples)) return {};
  if (components < 1 || components > (1u << 16) || size < 1 || size > 16 || type > 64 || type == VTK_BIT) return {};
  if (tuples > in.left() / size / components) return {};
  vtkSmartPointer<vtkDataArray> data = newArray(static_cast<int>(type), size, role);
  if (!data || !data->HasStandardMemoryLayout() || static_cast<std::uint64_t>(data->GetDataTypeSize()) != size)
    return {};
  data->SetNumberOfComponents(static_cast<int>(components));
  const auto values = static_cast<std::size_t>(tuples * components);
  if (!in.payload(data, values, values * static_cast<std::size_t>(size))) return {};
  if (!name.empty()) data->SetName(name.c_str());
  return {true, data};
}

/// `array` as a fresh array of class A (same values), or null when its value
/// type is not A's.
template <typename A>
vtkSmartPointer<A> as(vtkAbstractArray* array) {
  if (!array) return nullptr;
  if (auto* same = A::SafeDownCast(array)) return same;
  auto* data = vtkDataArray::SafeDownCast(array);
  vtkNew<A> probe;
  if (!data || data->GetDataTypeSize() != probe->GetDataTypeSize() ||
      floating(data->GetDataType()) != floating(probe->GetDataType()))
    return nullptr;
  auto out = vtkSmartPointer<A>::New();
  out->SetNumberOfComponents(data->GetNumberOfComponents());
  out->SetNumberOfTuples(data->GetNumberOfTuples());
  const std::size_t n =
      static_cast<std::size_t>(data->GetNumberOfValues()) * static_cast<std::size_t>(data->GetDataTypeSize());
  if (n > 0) std::memcpy(out->GetVoidPointer(0), data->GetVoidPointer(0), n);
  out->SetName(data->GetName());
  return out;
}

bool receiveFields(Receiver& in, vtkFieldData* fields) {
  std::uint64_t n = 0;
  if (!in.word(n) || n > in.left()) return false;
  for (std::uint64_t i = 0; i < n; ++i) {
    const Received r = receiveArray(in);
    if (!r.ok || !r.array) return false;
    fields->AddArray(r.array);
  }
  return true;
}

vtkSmartPointer<vtkUnstructuredGrid> receiveFrom(Receiver& in) {
  char magic[sizeof kMagic];
  if (!in.take(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof kMagic) != 0) return nullptr;
  // points, offsets, connectivity, types, faces, face locations
  const Role roles[6] = {Role::Any, Role::CellIds, Role::CellIds, Role::Types, Role::Ids, Role::Ids};
  Received slots[6];
  for (int k = 0; k < 6; ++k)
    if (slots[k] = receiveArray(in, roles[k]); !slots[k].ok) return nullptr;
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  if (slots[0].array) {
    auto* coordinates = vtkDataArray::SafeDownCast(slots[0].array);
    if (!coordinates || coordinates->GetNumberOfComponents() != 3) return nullptr;
    vtkNew<vtkPoints> points;
    points->SetData(coordinates);
    grid->SetPoints(points);
  }
  if (slots[1].array || slots[2].array || slots[3].array) {
    auto types = as<vtkUnsignedCharArray>(slots[3].array);
    if (!types || !slots[1].array || !slots[2].array) return nullptr;
    vtkNew<vtkCellArray> cells;
    auto* offsets = vtkDataArray::SafeDownCast(slots[1].array);
    if (!offsets || offsets->GetNumberOfComponents() != 1 || slots[2].array->GetNumberOfComponents() != 1)
      return nullptr;
    if (offsets->GetDataTypeSize() == 8) {
      auto o = as<vtkTypeInt64Array>(slots[1].array), c = as<vtkTypeInt64Array>(slots[2].array);
      if (!o || !c) return nullptr;
      cells->SetData(o, c);
    } else {
      auto o = as<vtkTypeInt32Array>(slots[1].array), c = as<vtkTypeInt32Array>(slots[2].array);
      if (!o || !c) return nullptr;
      cells->SetData(o, c);
    }
    vtkSmartPointer<vtkIdTypeArray> locations, faces;
    if (slots[4].array || slots[5].array) {
      faces = as<vtkIdTypeArray>(slots[4].array);
      locations = as<vtkIdTypeArray>(slots[5].array);
      if (!faces || !locations) return nullptr;
    }
    grid->SetCells(types, cells, locations, faces);
  }
  if (!receiveFields(in, grid->GetPointData()) || !receiveFields(in, grid->GetCellData()) ||
      !receiveFields(in, grid->GetFieldData()) || in.left() != 0)
    return nullptr;
  return grid;
}

}  // namespace

bool sendGrid(vtkUnstructuredGrid* grid, int fd) {
  Sender out(fd);
  out.bytes(kMagic, sizeof kMagic);
  vtkCellArray* cells = grid->GetCells();
  const bool sent = sendArray(out, grid->GetPoints() ? grid->GetPoints()->GetData() : nullptr) &&
                    sendArray(out, cells ? cells->GetOffsetsArray() : nullptr) &&
                    sendArray(out, cells ? cells->GetConnectivityArray() : nullptr) &&
                    sendArray(out, cells ? grid->GetCellTypesArray() : nullptr) &&
                    sendArray(out, grid->GetFaces()) && sendArray(out, grid->GetFaceLocations()) &&
                    sendFields(out, grid->GetPointData()) && sendFields(out, grid->GetCellData()) &&
                    sendFields(out, grid->GetFieldData());
  return out.finish() && sent;
}

vtkSmartPointer<vtkUnstructuredGrid> receiveGrid(int fd) {
  struct stat st {};
  if (::fstat(fd, &st) != 0 || st.st_size <= 0) return nullptr;
  Receiver in(fd, static_cast<std::size_t>(st.st_size));
  return receiveFrom(in);
}

}  // namespace tessella::io::detail
