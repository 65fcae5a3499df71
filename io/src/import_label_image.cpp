// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Label images read through VTK's image readers (TIFF, MetaImage, VTK XML image
// data; NRRD in nrrd_image.cpp) and imported as tissues (label_image_2d.cpp).

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <type_traits>

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkImageReader2.h>
#include <vtkMetaImageReader.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkTIFFReader.h>
#include <vtkSetGet.h>
#include <vtkType.h>
#include <vtkXMLImageDataReader.h>

#include "label_image_2d.hpp"
#include "nrrd_image.hpp"
#include "vtk_integer_types.hpp"
#include "tessella/io/import.hpp"
#include "tessella/io/label_image.hpp"
#include "tessella/tissue/errors.hpp"
#include "vtk_error_capture.hpp"

namespace tessella::io {

namespace {

template <typename T>
void copyLabels(const T* values, std::vector<std::int64_t>& labels, const std::string& file) {
  if constexpr (!std::is_integral_v<T>) {
    throw InputError("label image " + file + " holds non-integer values");
  } else {
    for (std::size_t i = 0; i < labels.size(); ++i) {
      if constexpr (std::is_unsigned_v<T> && sizeof(T) == 8)
        if (values[i] > static_cast<T>(std::numeric_limits<std::int64_t>::max()))
          throw InputError("label image " + file + ": pixel " + std::to_string(i) + " has label " +
                           std::to_string(values[i]) + ", beyond a 64-bit signed integer");
      labels[i] = static_cast<std::int64_t>(values[i]);
    }
  }
}

}  // namespace

namespace {

// An image read by VTK: its header (no labels yet) and its scalars, kept alive by `data`.
struct VtkImage {
  vtkSmartPointer<vtkImageData> data;
  vtkDataArray* scalars = nullptr;
  LabelImage header;
};

// VTK 9.1's vtkMetaImageReader corrupts memory on 64-bit element types (the process aborts or crashes inside
// its Update(), docs/import.md), so such a MetaImage is refused by its header before VTK reads it. The header is
// text lines "Key = Value"; ElementDataFile is its last one (in a .mha the raw pixels follow).
void refuseWideMetaImage(const std::string& path, const std::string& file) {
  std::ifstream in(path, std::ios::binary);
  const auto trimmed = [](const std::string& s) {
    const auto first = s.find_first_not_of(" \t\r");
    return first == std::string::npos ? std::string() : s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
  };
  std::string line;
  for (int n = 0; n < 200 && std::getline(in, line); ++n) {
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    std::string key = trimmed(line.substr(0, eq));
    std::transform(key.begin(), key.end(), key.begin(), [](unsigned char c) { return std::tolower(c); });
    const std::string value = trimmed(line.substr(eq + 1));
    if (key == "elementtype" && (value == "MET_LONG_LONG" || value == "MET_ULONG_LONG"))
      throw InputError("cannot read label image " + file + ": its MetaImage element type is " + value +
                       " (64-bit integers), which VTK's MetaImage reader does not read safely (it corrupts "
                       "memory); store the labels in 32 bits or as a .vti file");
    if (key == "elementdatafile") break;
  }
}

VtkImage readVtkImage(const std::string& path) {
  const std::string file = "'" + path + "'";
  if (!std::filesystem::is_regular_file(path)) throw InputError("cannot read label image " + file + ": no such file");
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  auto capture = vtkSmartPointer<detail::VtkErrorCapture>::New();
  VtkImage out;
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == ".nrrd" || ext == ".nhdr") {
    out.data = detail::readNrrdImage(path);
  } else if (ext == ".vti") {
    auto r = vtkSmartPointer<vtkXMLImageDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else {
    vtkSmartPointer<vtkImageReader2> r;
    if (ext == ".tif" || ext == ".tiff") {
      auto tiff = vtkSmartPointer<vtkTIFFReader>::New();
      tiff->SetOrientationType(1);  // see docs/import.md: the first row stored is j = 0, as NumPy reads it
      r = tiff;
    } else if (ext == ".mha" || ext == ".mhd") {
      refuseWideMetaImage(path, file);
      r = vtkSmartPointer<vtkMetaImageReader>::New();
    } else
      throw InputError("cannot read label image " + file + ": '" + ext +
                       "' is no image format read (.tif, .tiff, .nrrd, .nhdr, .mha, .mhd, .vti)");
    if (!r->CanReadFile(path.c_str()))
      throw InputError("cannot read label image " + file + ": not a readable " + ext + " file");
    r->SetFileName(path.c_str());
    reader = r;
  }
  if (reader) {
    capture->watch(reader);
    reader->Update();
    out.data = vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
    if (capture->failed() || !out.data)
      throw InputError("cannot read label image " + file + ": " +
                       (capture->failed() ? capture->message() : std::string("no image in the file")));
  }
  vtkImageData* data = out.data;
  vtkDataArray* scalars = data->GetPointData() ? data->GetPointData()->GetScalars() : nullptr;
  if (!scalars && data->GetPointData() && data->GetPointData()->GetNumberOfArrays() > 0)
    scalars = data->GetPointData()->GetArray(0);
  if (!scalars) throw InputError("label image " + file + " holds no pixel values");
  if (!detail::isVtkIntegerType(scalars->GetDataType()))
    throw InputError("label image " + file + " holds " + std::string(scalars->GetDataTypeAsString()) +
                     " values: a label image holds integers (one label per pixel), not intensities");
  if (scalars->GetNumberOfComponents() != 1)
    throw InputError("label image " + file + " has " + std::to_string(scalars->GetNumberOfComponents()) +
                     " components per pixel (colour?): a label image has one integer per pixel");
  LabelImage& img = out.header;
  img.name = path;
  int dims[3];
  data->GetDimensions(dims);
  double spacing[3], origin[3];
  data->GetSpacing(spacing);
  data->GetOrigin(origin);
  for (int k = 0; k < 3; ++k) img.dims[k] = dims[k], img.spacing[k] = spacing[k], img.origin[k] = origin[k];
  const vtkIdType n = scalars->GetNumberOfTuples();
  if (n != static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2])
    throw InputError("label image " + file + " has " + std::to_string(n) + " values for " + std::to_string(dims[0]) +
                     " x " + std::to_string(dims[1]) + " x " + std::to_string(dims[2]) + " pixels");
  out.scalars = scalars;
  return out;
}

// The image's labels copied into image.header.labels (64-bit).
LabelImage withLabels(VtkImage&& image) {
  LabelImage img = std::move(image.header);
  vtkDataArray* scalars = image.scalars;
  const std::string file = "'" + img.name + "'";
  img.labels.resize(static_cast<std::size_t>(scalars->GetNumberOfTuples()));
  switch (scalars->GetDataType()) {
    vtkTemplateMacro(copyLabels(static_cast<const VTK_TT*>(scalars->GetVoidPointer(0)), img.labels, file));
    default:
      throw InputError("label image " + file + ": unsupported scalar type " + scalars->GetDataTypeAsString());
  }
  return img;
}

// The scalars as they are stored, where every value is a label (not unsigned 64-bit).
template <typename T>
std::optional<detail::LabelPixels> storedPixels(const T* values) {
  if constexpr (std::is_constructible_v<detail::LabelPixels, const T*> && std::is_integral_v<T> &&
                !(std::is_unsigned_v<T> && sizeof(T) == 8))
    return detail::LabelPixels(values);
  else
    return std::nullopt;
}

}  // namespace

LabelImage readLabelImage(const std::string& path) { return withLabels(readVtkImage(path)); }

ImportResult importLabelImage(const std::string& path, const ImportOptions& options) {
  VtkImage image = readVtkImage(path);
  std::optional<detail::LabelPixels> pixels;
  if (image.header.dims[2] == 1) {  // 2D: read in place, without the 64-bit copy, where the type allows
    vtkDataArray* scalars = image.scalars;
    switch (scalars->GetDataType()) {
      vtkTemplateMacro(pixels = storedPixels(static_cast<const VTK_TT*>(scalars->GetVoidPointer(0))));
      default:
        break;
    }
  }
  ImportResult r =
      pixels ? detail::tissueFromLabelPixels2d(image.header, *pixels,
                                               static_cast<std::size_t>(image.scalars->GetNumberOfTuples()), options,
                                               [&] { image.scalars = nullptr, image.data = nullptr; })
             : tissueFromLabelImage(withLabels(std::move(image)), options);
  r.report.path = path;
  return r;
}

}  // namespace tessella::io
