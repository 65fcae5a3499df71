// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "vtu_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <regex>
#include <type_traits>
#include <utility>
#include <vector>

#include <SMP/Common/vtkSMPToolsAPI.h>  // vtkSMPTools.h itself does not compile as C++20
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <sys/mman.h>

#include "atomic_file.hpp"
#include "grid_transfer.hpp"
#include "tessella/tissue/errors.hpp"
#include "vtk_error_capture.hpp"
#include "worker_process.hpp"

namespace tessella::io::detail {

namespace fs = std::filesystem;

namespace {

// VTK reports a failed write in its own words only. The temporary file is
// created here first, so a missing directory, a missing permission or a
// read-only file system is reported with the operating system's reason.
void createWritable(const std::string& tmp, const std::string& path) {
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw InputError("cannot write '" + path + "': " + osReason(errno));
  ::close(fd);
}

// Why VTK's writer stopped: errno right after Write() (disk full, file too
// large, I/O error), else VTK's own message.
std::string writeFailure(int error, const VtkErrorCapture& errors) {
  for (const int known : {ENOSPC, EDQUOT, EFBIG, EIO, EROFS, EACCES, EPERM, ENOENT})
    if (error == known) return osReason(error);
  if (errors.message().find("disk space") != std::string::npos) return osReason(ENOSPC);
  return errors.failed() ? errors.message() : std::string("VTK's writer failed");
}

}  // namespace

void writeGridFile(vtkUnstructuredGrid* grid, const std::string& path, const VtuOptions& options) {
  if (options.compression_level < 1 || options.compression_level > 9)
    throw InputError("compression_level = " + std::to_string(options.compression_level) +
                     " is outside 1..9 (writing '" + path + "')");
  replaceAtomically(
      path,
      [&](const std::string& tmp) {
        createWritable(tmp, path);
        vtkNew<vtkXMLUnstructuredGridWriter> writer;
        vtkNew<VtkErrorCapture> errors;
        errors->watch(writer);
        writer->SetInputData(grid);
        writer->SetFileName(tmp.c_str());
        // Appended raw binary: no base64 inflation, and readers can seek.
        writer->SetDataModeToAppended();
        writer->EncodeAppendedDataOff();
        // 64-bit block headers: arrays over 4 GiB stay representable.
        writer->SetHeaderTypeToUInt64();
        writer->SetIdTypeToInt64();
        switch (options.compression) {
          case Compression::None: writer->SetCompressorTypeToNone(); break;
          case Compression::LZ4: writer->SetCompressorTypeToLZ4(); break;
          case Compression::ZLib: writer->SetCompressorTypeToZLib(); break;
        }
        if (options.compression != Compression::None)
          writer->SetCompressionLevel(options.compression_level);
        errno = 0;
        const int ok = writer->Write();
        const int error = errno;  // VTK writes through a std::ofstream: errno tells why it stopped
        if (!ok || errors->failed()) throw InputError("cannot write '" + path + "': " + writeFailure(error, *errors));
      },
      options.durable);
}

namespace {

// The component counts of the XML header (before the appended data), which
// VTK 9.1 takes as they are: a count past what any array of a tissue or a
// mesh has (2^32 + 1 for the points, say) keeps its reader busy for minutes.
void checkComponentCounts(const std::string& path) {
  constexpr std::size_t kMaxHeader = std::size_t{16} << 20;
  constexpr long kMaxComponents = 1 << 16;
  std::ifstream in(path, std::ios::binary);
  std::string header;
  std::vector<char> chunk(std::size_t{1} << 16);
  std::size_t appended = std::string::npos;
  while (in && header.size() < kMaxHeader && appended == std::string::npos) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    const std::size_t from = header.size() > 16 ? header.size() - 16 : 0;  // a marker across two chunks
    header.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    appended = header.find("<AppendedData", from);
  }
  if (appended != std::string::npos) header.resize(appended);
  static const std::regex count(R"re(NumberOfComponents\s*=\s*"([^"]*)")re");
  for (auto it = std::sregex_iterator(header.begin(), header.end(), count); it != std::sregex_iterator(); ++it) {
    const std::string value = (*it)[1].str();
    const bool digits =
        !value.empty() && value.size() <= 6 && value.find_first_not_of("0123456789") == std::string::npos;
    if (!digits || std::stol(value) < 1 || std::stol(value) > kMaxComponents)
      throw InputError("cannot read '" + path + "': an array has NumberOfComponents=\"" + value.substr(0, 40) +
                       "\" (expected 1 to " + std::to_string(kMaxComponents) + "); the file is corrupted");
  }
}

/// VTK's parse of `path` with `Reader`; InputError naming the path on every
/// error VTK reports. `kind` names the file type for the message.
template <typename Reader>
auto parseXml(const std::string& path, const char* kind) {
  vtkNew<Reader> reader;
  vtkNew<VtkErrorCapture> reader_errors;
  vtkNew<VtkErrorCapture> parser_errors;
  reader_errors->watch(reader);
  reader->SetReaderErrorObserver(reader_errors);
  reader->SetParserErrorObserver(parser_errors);
  if (!reader->CanReadFile(path.c_str())) throw InputError("cannot read '" + path + "': not a " + kind + " file");
  reader->SetFileName(path.c_str());
  reader->Update();
  if (reader_errors->failed() || parser_errors->failed()) {
    std::string what = reader_errors->message();
    if (parser_errors->failed()) what += (what.empty() ? "" : "; ") + parser_errors->message();
    throw InputError("cannot read '" + path + "': " + what);
  }
  vtkSmartPointer<std::remove_pointer_t<decltype(reader->GetOutput())>> out = reader->GetOutput();
  if (!out) throw InputError("cannot read '" + path + "': the reader produced no data");
  return out;
}

constexpr const char* kVtuKind = "VTK XML UnstructuredGrid (.vtu)";
constexpr const char* kVtpKind = "VTK XML PolyData (.vtp)";

/// The errors VTK printed (through its logger or output window) in `text`,
/// without decoration, joined by "; "; empty if there are none. VTK objects
/// the reader creates on its own (decompressors, arrays) report there
/// instead of to the reader's observers.
std::string printedVtkErrors(const std::string& text) {
  std::string plain;  // without terminal colour codes
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\x1b' && i + 1 < text.size() && text[i + 1] == '[') {
      const auto end = text.find('m', i);
      if (end == std::string::npos) break;
      i = end;
    } else {
      plain += text[i];
    }
  }
  std::vector<std::string> errors;
  std::size_t start = 0;
  bool next_is_error = false;
  while (start < plain.size()) {
    const auto eol = std::min(plain.find('\n', start), plain.size());
    std::string line = plain.substr(start, eol - start);
    start = eol + 1;
    std::string message;
    if (const auto tag = line.find("ERR| "); tag != std::string::npos) message = line.substr(tag + 5);
    else if (next_is_error) message = line;
    next_is_error = line.rfind("ERROR: In ", 0) == 0;
    if (message.empty()) continue;
    // "vtkClass (0x1234): what" -> "what"
    if (const auto colon = message.find("): "); message.rfind("vtk", 0) == 0 && colon != std::string::npos)
      message = message.substr(colon + 3);
    while (!message.empty() && (message.back() == '.' || message.back() == ' ')) message.pop_back();
    if (!message.empty() && std::find(errors.begin(), errors.end(), message) == errors.end()) errors.push_back(message);
  }
  std::string joined;
  for (std::size_t i = 0; i < errors.size() && i < 3; ++i) joined += (i ? "; " : "") + errors[i];
  return joined.size() > 400 ? joined.substr(0, 400) + "..." : joined;
}

template <typename Offset>
void checkOffsets(const Offset* offsets, vtkIdType count, vtkIdType connectivity_size, const std::string& path) {
  const auto fail = [&](const std::string& what) { throw InputError("cannot read '" + path + "': " + what); };
  if (offsets[0] != 0) fail("the cell offsets start at " + std::to_string(offsets[0]) + ", not 0");
  for (vtkIdType i = 1; i < count; ++i)
    if (offsets[i] < offsets[i - 1])
      fail("the cell offsets decrease at cell " + std::to_string(i - 1) + " (" + std::to_string(offsets[i - 1]) +
           ", then " + std::to_string(offsets[i]) + ")");
  if (offsets[count - 1] != connectivity_size)
    fail("the cell offsets end at " + std::to_string(offsets[count - 1]) + " but the connectivity has " +
         std::to_string(connectivity_size) + " entries");
}

/// What tells one file from another, or the same file rewritten.
struct FileIdentity {
  dev_t device = 0;
  ino_t inode = 0;
  off_t size = 0;
  timespec modified{};
  bool operator==(const FileIdentity& o) const {
    return device == o.device && inode == o.inode && size == o.size && modified.tv_sec == o.modified.tv_sec &&
           modified.tv_nsec == o.modified.tv_nsec;
  }
};

FileIdentity identityOf(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InputError("cannot read '" + path + "': " + std::strerror(errno));
  return {st.st_dev, st.st_ino, st.st_size, st.st_mtim};
}

}  // namespace

namespace {

/// A file of this process's memory the worker hands a parsed grid over in.
struct MemoryFile {
  int fd = -1;
  MemoryFile() : fd(::memfd_create("tessella-grid", MFD_CLOEXEC)) {}
  ~MemoryFile() {
    if (fd >= 0) ::close(fd);
  }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;
};

constexpr const char* kHandedOver = "handed over";

/// `check`, when given, runs on the parsed grid in the worker, which then
/// writes the grid to a memory file that this process reads it back from.
template <typename Reader>
auto readXmlFile(const std::string& path, const char* kind,
                 const std::function<void(vtkUnstructuredGrid*)>& check = {}) {
  using Output = std::remove_pointer_t<decltype(std::declval<Reader&>().GetOutput())>;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError("cannot read '" + path + "': no such file");
  if (!fs::is_regular_file(path, ec)) throw InputError("cannot read '" + path + "': not a regular file");
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError("cannot read '" + path + "': " + osReason(errno));  // e.g. Permission denied
  ::close(fd);
  const FileIdentity before = identityOf(path);
  checkComponentCounts(path);

  // VTK 9.1's XML reader believes what the file says: a damaged type name,
  // header type, size or offset can make it follow a bad pointer, divide by
  // zero or allocate without bound. So a worker process parses the file
  // first, with a memory and a time limit; this process parses it only when
  // the worker could.
  const std::size_t size = static_cast<std::size_t>(before.size);
  const MemoryFile memory;
  const std::size_t memory_budget = (std::size_t{2} << 30) + 32 * size;
  const double timeout_seconds = 60.0 + static_cast<double>(size) / 1e6;
  const WorkerOutcome outcome = runInWorker(
      [&] {
        // A thread pool VTK's SMP tools (TBB) may have started in this
        // process does not exist in the worker: run sequentially.
        vtk::detail::smp::vtkSMPToolsAPI::GetInstance().SetBackend("Sequential");
        try {
          auto parsed = parseXml<Reader>(path, kind);
          if constexpr (std::is_same_v<Output, vtkUnstructuredGrid>) {
            if (check) {
              check(parsed);
              if (memory.fd >= 0 && sendGrid(parsed, memory.fd)) return std::string(kHandedOver);
            }
          }
        } catch (const std::bad_alloc&) {
          throw;
        } catch (const InputError&) {
          throw;
        } catch (const std::exception& e) {
          throw InputError("cannot read '" + path + "': the VTK reader failed on this file (" + e.what() +
                           "); the file is corrupted");
        }
        return std::string();
      },
      memory_budget, timeout_seconds);
  if (outcome.threw) throw InputError(outcome.output);
  if (!outcome.ok)
    throw InputError("cannot read '" + path + "': the VTK reader " + outcome.output +
                     " on this file; the file is corrupted");
  if (const std::string errors = printedVtkErrors(outcome.printed); !errors.empty())
    throw InputError("cannot read '" + path + "': " + errors + "; the file is corrupted");

  vtkSmartPointer<Output> grid;
  if constexpr (std::is_same_v<Output, vtkUnstructuredGrid>)
    if (outcome.output == kHandedOver) grid = receiveGrid(memory.fd);
  if (!grid) {
    grid = parseXml<Reader>(path, kind);
    if constexpr (std::is_same_v<Output, vtkUnstructuredGrid>)
      if (check) check(grid);
  }
  if (!(identityOf(path) == before))
    throw InputError("cannot read '" + path + "': the file changed while it was being read");
  return grid;
}

}  // namespace

vtkSmartPointer<vtkUnstructuredGrid> readGridFile(const std::string& path) {
  return readXmlFile<vtkXMLUnstructuredGridReader>(path, kVtuKind);
}

vtkSmartPointer<vtkUnstructuredGrid> readGridFile(const std::string& path,
                                                  const std::function<void(vtkUnstructuredGrid*)>& check) {
  return readXmlFile<vtkXMLUnstructuredGridReader>(path, kVtuKind, check);
}

vtkSmartPointer<vtkPolyData> readPolyDataFile(const std::string& path) {
  return readXmlFile<vtkXMLPolyDataReader>(path, kVtpKind);
}

void checkCellArrays(vtkUnstructuredGrid* grid, const std::string& path) {
  const auto fail = [&](const std::string& what) { throw InputError("cannot read '" + path + "': " + what); };
  if (vtkPoints* points = grid->GetPoints(); points && points->GetData()->GetNumberOfComponents() != 3)
    fail("the points have " + std::to_string(points->GetData()->GetNumberOfComponents()) + " components, not 3");
  vtkCellArray* cells = grid->GetCells();
  if (!cells) return;
  const vtkIdType num_offsets = cells->GetNumberOfOffsets();
  const vtkIdType num_cells = cells->GetNumberOfCells();
  if (num_offsets == 0) return;
  vtkUnsignedCharArray* types = grid->GetCellTypesArray();
  const vtkIdType num_types = types ? types->GetNumberOfValues() : 0;
  if (num_types != num_cells)
    fail("the file has " + std::to_string(num_types) + " cell types for " + std::to_string(num_cells) + " cells");
  if (cells->IsStorage64Bit())
    checkOffsets(cells->GetOffsetsArray64()->GetPointer(0), num_offsets, cells->GetNumberOfConnectivityIds(), path);
  else
    checkOffsets(cells->GetOffsetsArray32()->GetPointer(0), num_offsets, cells->GetNumberOfConnectivityIds(), path);
}

void checkPolyArrays(vtkPolyData* data, const std::string& path) {
  const auto fail = [&](const std::string& what) { throw InputError("cannot read '" + path + "': " + what); };
  if (vtkPoints* points = data->GetPoints(); points && points->GetData()->GetNumberOfComponents() != 3)
    fail("the points have " + std::to_string(points->GetData()->GetNumberOfComponents()) + " components, not 3");
  vtkCellArray* polys = data->GetPolys();
  if (!polys || polys->GetNumberOfOffsets() == 0) return;
  const vtkIdType n = polys->GetNumberOfOffsets();
  if (polys->IsStorage64Bit())
    checkOffsets(polys->GetOffsetsArray64()->GetPointer(0), n, polys->GetNumberOfConnectivityIds(), path);
  else
    checkOffsets(polys->GetOffsetsArray32()->GetPointer(0), n, polys->GetNumberOfConnectivityIds(), path);
}

}  // namespace tessella::io::detail
