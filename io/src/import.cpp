// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The table of import formats and the format-independent entry point.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "tessella/io/import.hpp"
#include "tessella/io/ply.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::io {

const std::vector<ImportFormat>& importFormats() {
  static const std::vector<ImportFormat> formats = {
      {"morphographx",
       {".ply"},
       "MorphoGraphX PLY cell mesh: triangles with a per-face cell `label` (a curved 2.5D sheet)",
       &importMorphoGraphX,
       &isMorphoGraphXMesh},
      {"cell_complex",
       {".ply"},
       "cell-complex PLY (OpenAlea property topomesh): vertex, face, edge and volume elements; closed volumes give a "
       "3D tissue, open patches of one surface a curved sheet",
       &importCellComplex,
       &isCellComplexPly},
      {"labelled_mesh",
       {".ply", ".obj", ".vtp"},
       "polygon mesh with integer cell labels per face (PLY face property, OBJ `g LABEL` groups, VTK PolyData "
       "cell data; label_array picks it): one label per face gives a curved sheet, two (the cells on either "
       "side) a 3D tissue",
       &importLabelledMesh,
       &isLabelledMesh},
      {"labelled_vtu",
       {".vtu"},
       "VTK mesh with a per-element cell label (label, cell_label or cell_id): tetrahedra give a 3D tissue "
       "(walls: the triangles between labels), triangles a curved sheet",
       &importLabelledVtu,
       &isLabelledVtu},
      {"label_image",
       {".tif", ".tiff", ".nrrd", ".nhdr", ".mha", ".mhd", ".vti"},
       "segmented 2D or 3D label image (one integer label per pixel or voxel; TIFF, NRRD, MetaImage, VTK image "
       "data): each label a cell of a planar or a 3D tissue, walls along the pixel edges or voxel faces between "
       "labels",
       &importLabelImage,
       nullptr},
  };
  return formats;
}

std::vector<std::string> importFormatNames() {
  std::vector<std::string> names{"auto"};
  for (const ImportFormat& f : importFormats()) names.push_back(f.name);
  return names;
}

std::string importFormatList() {
  std::string out;
  for (const ImportFormat& f : importFormats()) {
    out += "  " + f.name + " (";
    for (std::size_t i = 0; i < f.extensions.size(); ++i) out += (i ? ", " : "") + f.extensions[i];
    out += "): " + f.description + "\n";
  }
  return out;
}

namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// "vertex(x, y, z, ...) face(...)": what a PLY file holds, for an error message.
std::string plyLayout(const std::string& path) {
  const PlyHeader h = readPlyHeader(path);
  std::string out;
  for (const PlyElement& e : h.elements) {
    if (!out.empty()) out += ", ";
    out += e.name + "(";
    for (std::size_t i = 0; i < e.properties.size(); ++i) out += (i ? " " : "") + e.properties[i].name;
    out += ")";
  }
  return out.empty() ? "no elements" : out;
}

}  // namespace

const ImportFormat& detectImportFormat(const std::string& path) {
  const std::string ext = lowerExtension(path);
  std::vector<const ImportFormat*> candidates;
  for (const ImportFormat& f : importFormats())
    if (std::find(f.extensions.begin(), f.extensions.end(), ext) != f.extensions.end()) candidates.push_back(&f);
  if (candidates.empty())
    throw InputError("cannot import '" + path + "': no import format reads " +
                     (ext.empty() ? std::string("files without an extension") : "'" + ext + "' files") +
                     "; supported formats:\n" + importFormatList());
  for (const ImportFormat* f : candidates)
    if (!f->recognises || f->recognises(path)) return *f;
  std::string layout;
  std::string hint;
  if (ext == ".ply") {
    layout = " (it holds " + plyLayout(path) + ")";
    hint = " (a labelled mesh whose face label property has another name: give its name as label_array, "
           "--label-array)";
  }
  throw InputError("cannot import '" + path + "': its layout" + layout + " is none of the supported formats" + hint +
                   "; supported formats:\n" + importFormatList());
}

ImportResult importTissue(const std::string& path, const ImportOptions& options) {
  const ImportFormat* format = nullptr;
  if (options.format == "auto" && !options.label_array.empty()) {
    // A label array names a labelled format: the one reading this extension.
    const std::string ext = lowerExtension(path);
    for (const ImportFormat& f : importFormats())
      if (!format && (f.name == "labelled_mesh" || f.name == "labelled_vtu") &&
          std::find(f.extensions.begin(), f.extensions.end(), ext) != f.extensions.end())
        format = &f;
    if (!format)
      throw InputError("cannot import '" + path + "': label_array ('" + options.label_array +
                       "') applies to the labelled_mesh and labelled_vtu formats, which do not read '" + ext +
                       "' files");
  } else if (options.format == "auto") {
    format = &detectImportFormat(path);
  } else {
    for (const ImportFormat& f : importFormats())
      if (f.name == options.format) format = &f;
    if (!format)
      throw InputError("unknown import format '" + options.format + "'; choose auto or one of:\n" +
                       importFormatList());
  }
  if (!options.label_array.empty() && format->name != "labelled_mesh" && format->name != "labelled_vtu")
    throw InputError("cannot import '" + path + "': label_array ('" + options.label_array +
                     "') applies to the labelled_mesh and labelled_vtu formats, not " + format->name);
  if (format->name != "label_image" && options.image != LabelImageOptions{})
    throw InputError("cannot import '" + path + "': the label-image options (voxel_size, background, drop_labels, "
                     "min_cell_size, small_cells, crop, keep_pieces) apply to label images only, not to " +
                     format->name);
  ImportResult result = format->read(path, options);
  result.report.format = format->name;
  return result;
}

}  // namespace tessella::io
