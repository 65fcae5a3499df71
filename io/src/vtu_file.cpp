#include "vtu_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>

#include <vtkNew.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "atomic_file.hpp"
#include "tessella/tissue/errors.hpp"
#include "vtk_error_capture.hpp"

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

vtkSmartPointer<vtkUnstructuredGrid> readGridFile(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError("cannot read '" + path + "': no such file");
  if (!fs::is_regular_file(path, ec)) throw InputError("cannot read '" + path + "': not a regular file");

  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError("cannot read '" + path + "': " + osReason(errno));  // e.g. Permission denied
  ::close(fd);

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  vtkNew<VtkErrorCapture> reader_errors;
  vtkNew<VtkErrorCapture> parser_errors;
  reader_errors->watch(reader);
  reader->SetReaderErrorObserver(reader_errors);
  reader->SetParserErrorObserver(parser_errors);
  if (!reader->CanReadFile(path.c_str()))
    throw InputError("cannot read '" + path + "': not a VTK XML UnstructuredGrid (.vtu) file");
  reader->SetFileName(path.c_str());
  reader->Update();
  if (reader_errors->failed() || parser_errors->failed()) {
    std::string what = reader_errors->message();
    if (parser_errors->failed()) what += (what.empty() ? "" : "; ") + parser_errors->message();
    throw InputError("cannot read '" + path + "': " + what);
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  if (!grid) throw InputError("cannot read '" + path + "': the reader produced no grid");
  return grid;
}

}  // namespace tessella::io::detail
