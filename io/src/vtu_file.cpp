#include "vtu_file.hpp"

#include <filesystem>

#include <vtkNew.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "atomic_file.hpp"
#include "tessella/tissue/errors.hpp"
#include "vtk_error_capture.hpp"

namespace tessella::io::detail {

namespace fs = std::filesystem;

void writeGridFile(vtkUnstructuredGrid* grid, const std::string& path, const VtuOptions& options) {
  if (options.compression_level < 1 || options.compression_level > 9)
    throw InputError("compression_level = " + std::to_string(options.compression_level) +
                     " is outside 1..9 (writing '" + path + "')");
  replaceAtomically(
      path,
      [&](const std::string& tmp) {
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
        const int ok = writer->Write();
        if (!ok || errors->failed())
          throw InputError("cannot write '" + path + "': " +
                           (errors->failed() ? errors->message() : std::string("VTK writer failed")));
      },
      options.durable);
}

vtkSmartPointer<vtkUnstructuredGrid> readGridFile(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError("cannot read '" + path + "': no such file");
  if (!fs::is_regular_file(path, ec)) throw InputError("cannot read '" + path + "': not a regular file");

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
