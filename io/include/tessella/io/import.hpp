// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Importing segmented tissues from other tools' files. One table,
// importFormats(), lists every format (name, file extensions, reader); the
// CLI (`tessella import`), the YAML generator (`tissue.generator: import`),
// the Python module and docs/import.md all use it, so a new format is one row.
//
// Every importer is strict: a malformed or inconsistent file is an
// InputError naming the file, the line or element index and the cell label,
// and nothing is built. `repair` fixes only the harmless defects a format's
// importer lists (docs/import.md), each reported in ImportReport::repairs.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "tessella/tissue/tissue.hpp"

namespace tessella::io {

/// Options of the label_image format (docs/import.md, "Label images").
struct LabelImageOptions {
  /// Pixel size (x, y) or voxel size (x, y, z), overriding the file's; empty:
  /// the file's spacing (1 where the file has none).
  std::vector<double> voxel_size;
  /// Labels that are no cell (PlantSeg and MARS use 0 and 1).
  std::vector<std::int64_t> background{0, 1};
  /// Labels dropped (made background) before anything else.
  std::vector<std::int64_t> drop_labels;
  /// Labels with fewer pixels are dropped or merged (small_cells); 0 keeps all.
  std::int64_t min_cell_size = 0;
  /// "drop" (make them background) or "merge" (into the neighbour sharing
  /// the longest wall).
  std::string small_cells = "drop";
  /// Empty, or {x0, y0, x1, y1}: the pixels x0 <= i < x1, y0 <= j < y1 only.
  std::vector<std::int64_t> crop;
  /// A label in several disconnected pieces: an error (false) or one cell
  /// per piece, each keeping the label (true).
  bool keep_pieces = false;

  bool operator==(const LabelImageOptions&) const = default;
};

struct ImportOptions {
  /// A row of importFormats() by name, or "auto": chosen from the file's
  /// extension and, where several formats share it, from its contents.
  std::string format = "auto";
  /// Multiplies every position (the file's units are kept with 1).
  double scale = 1.0;
  /// Douglas-Peucker tolerance for wall polylines between junctions, in the
  /// file's units times `scale`; 0 keeps every wall vertex.
  double simplify = 0.0;
  /// Fix the harmless defects the format's importer knows (and report them).
  bool repair = false;
  /// The array (PLY face property, VTK cell-data array; for OBJ the label
  /// statement: g, o or usemtl) holding each face's cell label, for the
  /// labelled_mesh and labelled_vtu formats; "A,B" names two, the cells on
  /// either side of each face (a 3D tissue). Empty: the first of label,
  /// cell_label, cell_id present, else the pair label_front, label_back.
  std::string label_array = "";
  /// For label images only (format label_image); `simplify` is then in pixels.
  LabelImageOptions image;
};

struct ImportReport {
  std::string path;
  std::string format;  ///< the importFormats() row used
  /// Counts in the file.
  std::size_t file_vertices = 0, file_faces = 0;
  /// What file_faces counts: "faces", or "elements" for a VTK mesh.
  std::string file_faces_noun = "faces";
  /// Vertices removed by `simplify` (0 without).
  std::size_t simplified_vertices = 0;
  /// One line per repair made (empty without `repair`).
  std::vector<std::string> repairs;
  /// Other facts worth telling (dropped unused vertices, kept properties).
  std::vector<std::string> notes;
};

struct ImportResult {
  Tissue tissue;
  ImportReport report;
};

/// One importable format.
struct ImportFormat {
  std::string name;                     ///< "morphographx", ...
  std::vector<std::string> extensions;  ///< lower case, with the dot: ".ply"
  std::string description;              ///< one line, for help texts and errors
  ImportResult (*read)(const std::string& path, const ImportOptions& options);
  /// For "auto" when several formats share an extension: whether the file
  /// has this format's layout (reads the header only). Null: extension only.
  bool (*recognises)(const std::string& path);
};

/// Every importable format.
const std::vector<ImportFormat>& importFormats();
/// The names of importFormats() plus "auto".
std::vector<std::string> importFormatNames();
/// "name (.ext, ...): description" lines, one per format.
std::string importFormatList();
/// The format "auto" picks for `path`; InputError naming the file and listing
/// the supported formats when none fits.
const ImportFormat& detectImportFormat(const std::string& path);

/// Imports a tissue in any format of the table. InputError for an unknown
/// format name, a bad option (scale <= 0, simplify < 0, not finite) or a bad file.
ImportResult importTissue(const std::string& path, const ImportOptions& options = {});

// --- MorphoGraphX -------------------------------------------------------------

/// A MorphoGraphX PLY cell mesh (2.5D): per vertex x y z and `label` (-1 on
/// walls), optional `parent`; per face a vertex list (`vertex_index` or
/// `vertex_indices`) and `label`. Each label's triangles form one cell, whose
/// outline (the boundary of their union) becomes a polygon of a curved-sheet
/// tissue (Embedding::Surface); wall vertices stay shared. Cell properties:
/// `label` (int64) and, when the file has vertex `parent`, `parent` (int64,
/// the parent of the cell's centre vertex, 0 = unknown).
ImportResult importMorphoGraphX(const std::string& path, const ImportOptions& options = {});
/// Whether a PLY file has the MorphoGraphX cell-mesh layout (vertex `label`
/// and face `label` properties).
bool isMorphoGraphXMesh(const std::string& path);

// --- cell-complex PLY ----------------------------------------------------------

/// A cell-complex PLY file, the "property topomesh" layout of the OpenAlea
/// cellcomplex tools: element `vertex` (x y z), `face` (a vertex loop,
/// `vertex_index` or `vertex_indices`, or an edge list `edge_index`),
/// optional `edge` (source target), `volume` (`face_index`: its faces,
/// 0-based, or signed 1-based +-(face + 1) as OpenAlea's oriented writer puts
/// them; optional `label`, else the volume index). When every volume is a
/// closed surface: a 3D tissue whose walls are the file's faces (each shared
/// by the one or two volumes listing it), oriented so that every cell is
/// closed and outward. When every volume is an open patch (a disk) of one
/// surface: a curved-sheet tissue of the patches' outlines, as for
/// MorphoGraphX. Cell property `label` (int64). The report's notes say which.
ImportResult importCellComplex(const std::string& path, const ImportOptions& options = {});
/// Whether a PLY file has the cell-complex layout (vertex, face and volume
/// elements, volume `face_index`).
bool isCellComplexPly(const std::string& path);

// --- labelled VTK meshes ----------------------------------------------------------

/// A VTK unstructured grid (.vtu) whose elements carry an integer cell-data
/// array naming the cell they lie in (`label`, `cell_label` or `cell_id`,
/// the first present; `tessella mesh` writes `cell_id`). Tetrahedra: a 3D
/// tissue whose walls are the triangles between elements of different
/// labels and on the mesh's boundary, each triangle one wall (the closed-cell
/// core of importCellComplex). Triangles or polygons: a curved-sheet tissue
/// of each label's outline (the core of importMorphoGraphX). Cell property
/// `label` (int64).
ImportResult importLabelledVtu(const std::string& path, const ImportOptions& options = {});
/// Whether a .vtu file declares a cell-data array named label, cell_label or
/// cell_id and is not a Tessella snapshot (reads the XML header only).
bool isLabelledVtu(const std::string& path);

// --- generic labelled meshes ------------------------------------------------------

/// A polygon mesh in PLY (ASCII or binary), Wavefront OBJ or VTK PolyData
/// (.vtp) whose faces carry integer cell labels (ImportOptions::label_array;
/// OBJ: the integer names of `g` groups). One label per face: each label's
/// faces are a patch of one surface, and the tissue is the curved sheet of
/// the patches' outlines (the core of importMorphoGraphX). Two labels per
/// face (the cells on either side, <= 0 for the outside): each label's faces
/// bound a closed cell, a 3D tissue whose walls are the faces (the core of
/// importCellComplex). Cell property `label` (int64).
ImportResult importLabelledMesh(const std::string& path, const ImportOptions& options = {});
/// Whether a file could be a labelled mesh: any .obj or .vtp; a .ply with
/// vertex and face elements and a face vertex list (reads the header only).
bool isLabelledMesh(const std::string& path);
// --- label images -----------------------------------------------------------------

/// A segmented label image (TIFF, NRRD, MetaImage .mha/.mhd, VTK .vti). 2D (a
/// 3D file with one z layer counts as 2D): each label not in
/// options.image.background a cell of a planar tissue, walls along the pixel
/// edges between labels, simplified (options.simplify, in pixels) with
/// junctions fixed. 3D: each label a closed cell of a 3D tissue, one wall per
/// connected interface between two labels, bounded by the junction lines
/// where three or more labels meet (docs/import.md, "3D label images").
/// Cell property `label` (int64). label_image.hpp holds the in-memory form (a
/// NumPy array from Python).
ImportResult importLabelImage(const std::string& path, const ImportOptions& options = {});

/// A MorphoGraphX cell graph (cellGraph_*.ply): one vertex per cell with its
/// label and `Geometry/Area`, one edge per neighbour pair listing the two
/// cells' labels (MorphoGraphX 2.0 writes labels, not vertex indices).
struct MorphoGraphXCellGraph {
  std::vector<std::int64_t> labels;
  std::vector<double> areas;  ///< empty when the file has no Geometry/Area
  /// As listed in the file (MorphoGraphX lists each pair in both directions,
  /// some twice): see neighbourPairs() for the set.
  std::vector<std::pair<std::int64_t, std::int64_t>> edges;
  /// The distinct unordered pairs (smaller label first), sorted.
  std::vector<std::pair<std::int64_t, std::int64_t>> neighbourPairs() const;
};
/// InputError for a duplicated label, an edge naming no listed label, a self loop.
MorphoGraphXCellGraph readMorphoGraphXCellGraph(const std::string& path);

}  // namespace tessella::io
