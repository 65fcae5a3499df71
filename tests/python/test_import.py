# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# Importing segmented tissues from Python: tessella.import_tissue and
# import_tissue_with_report (docs/import.md), on the bundled real meristem
# (tests/data/mgx_meristem_cropped) and on small files written here.
import pytest

import tessella


def mgx_square_pair(path, labels=(3, 8), last_index=None):
    """Two unit squares side by side, each a fan of 4 triangles around its centre."""
    walls = [(0, 0), (1, 0), (2, 0), (2, 1), (1, 1), (0, 1)]
    centres = [(0.5, 0.5), (1.5, 0.5)]
    vertices = [(x, y, 0.0, -1, 0) for x, y in walls]
    vertices += [(x, y, 0.0, lab, 100 + lab) for (x, y), lab in zip(centres, labels)]
    loops = [[0, 1, 4, 5], [1, 2, 3, 4]]
    faces = []
    for c, loop in enumerate(loops):
        for k in range(4):
            faces.append((6 + c, loop[k], loop[(k + 1) % 4], labels[c]))
    if last_index is not None:
        faces[-1] = faces[-1][:2] + (last_index,) + faces[-1][3:]
    lines = ["ply", "format ascii 1.0", f"element vertex {len(vertices)}", "property float x", "property float y",
             "property float z", "property int label", "property int parent", f"element face {len(faces)}",
             "property list uchar int vertex_index", "property int label", "end_header"]
    lines += [" ".join(str(v) for v in vertex) for vertex in vertices]
    lines += [f"3 {a} {b} {c} {lab}" for a, b, c, lab in faces]
    path.write_text("\n".join(lines) + "\n")
    return str(path)


def test_import_keeps_labels_parents_and_scale(tmp_path):
    path = mgx_square_pair(tmp_path / "pair.ply")
    t = tessella.import_tissue(path, scale=2.0)
    assert t.num_cells == 2 and t.dim == 2
    assert list(t.property("label")) == [3, 8]
    assert list(t.property("parent")) == [103, 108]
    assert [t.cell_measure(c) for c in t.cells()] == [pytest.approx(4.0), pytest.approx(4.0)]
    assert t.validate()[0]
    t2, report = tessella.import_tissue_with_report(path, simplify=1e-9)
    assert report["format"] == "morphographx"
    assert report["file_faces"] == 8 and report["repairs"] == []
    assert report["simplified_vertices"] == 0  # every wall vertex is a corner here
    assert "auto" in tessella.import_formats() and "morphographx" in tessella.import_formats()


def test_import_errors_name_the_file_face_and_label(tmp_path):
    path = mgx_square_pair(tmp_path / "bad.ply", last_index=42)
    with pytest.raises(tessella.InputError, match=r"bad.ply' face 7 \(cell label 8\): vertex index 42 is out of range"):
        tessella.import_tissue(path)
    with pytest.raises(ValueError, match=r"unknown import format 'vtk'"):
        tessella.import_tissue(path, format="vtk")


def test_import_real_meristem(source_dir):
    path = source_dir / "tests/data/mgx_meristem_cropped/mesh_meristem_cropped_T0.ply"
    t, report = tessella.import_tissue_with_report(str(path))
    assert t.num_cells == 128
    assert report["file_vertices"] == 1506 and report["file_faces"] == 2704
    assert len(set(t.property("label"))) == 128
    assert t.validate()[0]


def test_cell_complex_round_trip_3d_and_sheet(tmp_path):
    """export_cell_complex writes what import_tissue reads back: same cells, same measures."""
    box = tessella.box_grid(3, 2, 2, 1.0, 0.5, 2.0)
    info = tessella.export_cell_complex(box, str(tmp_path / "box.ply"))
    assert info["volumes"] == 12 and info["label_source"] == "lineage_id"
    back, report = tessella.import_tissue_with_report(str(tmp_path / "box.ply"))
    assert report["format"] == "cell_complex" and report["file_faces_noun"] == "faces"
    assert report["notes"][0].startswith("layout: closed volumes, a 3D tissue")
    assert back.dim == 3 and back.num_cells == 12 and back.validate()[0]
    assert [back.cell_measure(c) for c in back.cells()] == [pytest.approx(1.0, rel=1e-12)] * 12
    sheet = tessella.rectangular_grid(3, 2)
    tessella.export_cell_complex(sheet, str(tmp_path / "sheet.ply"), binary=True)
    back, report = tessella.import_tissue_with_report(str(tmp_path / "sheet.ply"), format="cell_complex")
    assert report["notes"][0].startswith("layout: open patches of one surface")
    assert back.dim == 2 and back.num_cells == 6
    assert [back.cell_measure(c) for c in back.cells()] == [pytest.approx(1.0, rel=1e-12)] * 6


def test_cell_complex_errors_name_the_volume_and_label(tmp_path):
    path = tmp_path / "bad.ply"
    path.write_text("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face 3\nproperty list uchar int vertex_index\n"
                    "element volume 1\nproperty list uchar int face_index\nproperty int label\nend_header\n"
                    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 1 7 12\n")
    with pytest.raises(tessella.InputError, match=r"bad.ply' volume 0 \(label 12\): face index 7 is out of range"):
        tessella.import_tissue(str(path))


def test_import_labelled_mesh_with_label_array(tmp_path):
    """labelled_mesh: an OBJ by its g groups, a PLY whose label property is named by label_array."""
    obj = tmp_path / "squares.obj"
    obj.write_text("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\n"
                   "g 5\nf 1 2 5\nf 1 5 4\ng 2\nf 2 3 6\nf 2 6 5\n")
    t, report = tessella.import_tissue_with_report(str(obj))
    assert report["format"] == "labelled_mesh"
    assert list(t.property("label")) == [2, 5]
    assert [t.cell_measure(c) for c in t.cells()] == [pytest.approx(1.0, rel=1e-14)] * 2
    assert "labelled_mesh" in tessella.import_formats()
    ply = tmp_path / "seg.ply"
    ply.write_text("ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
                   "element face 4\nproperty list uchar int vertex_indices\nproperty int segment\nend_header\n"
                   "0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n3 0 1 4 5\n3 0 4 3 5\n3 1 2 5 2\n3 1 5 4 2\n")
    with pytest.raises(tessella.InputError, match=r"none of the supported formats.*label-array"):
        tessella.import_tissue(str(ply))
    t = tessella.import_tissue(str(ply), label_array="segment", scale=3.0)
    assert list(t.property("label")) == [2, 5]
    assert [t.cell_measure(c) for c in t.cells()] == [pytest.approx(9.0, rel=1e-14)] * 2
    with pytest.raises(tessella.InputError, match=r"seg.ply': element 'face' has no cell label property 'region'"):
        tessella.import_tissue(str(ply), format="labelled_mesh", label_array="region")
