# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# Label images from Python: NumPy arrays and image files into planar and 3D tissues
# (docs/import.md, "Label images"), checked against closed forms (rectangles
# of pixels) and against the Voronoi tissue they were rasterised from.
import numpy as np
import pytest
from PIL import Image

import tessella


def labels_of(t):
    return list(t.property("label"))


def test_rectangles_of_pixels_have_exact_areas_and_neighbours():
    # Three labels in columns, array indexed [y, x]: 3 rows, 2 + 3 + 4 columns.
    a = np.zeros((3, 9), dtype=np.uint16)
    a[:, 0:2] = 5
    a[:, 2:5] = 7
    a[:, 5:9] = 9
    t, report = tessella.tissue_from_label_image_with_report(a, voxel_size=(0.5, 2.0))
    assert report["format"] == "label_image" and report["file_faces"] == 27
    assert labels_of(t) == [5, 7, 9]
    np.testing.assert_allclose(t.cell_measures(), [2 * 3 * 1.0, 3 * 3 * 1.0, 4 * 3 * 1.0], rtol=1e-12)
    # The image spans [0, 9 * 0.5] x [0, 3 * 2]; rectangles keep their 4 corners only.
    p = t.positions()
    assert p[:, 0].min() == 0 and p[:, 0].max() == 4.5 and p[:, 1].max() == 6.0
    assert t.num_vertices == 8
    assert sorted(len(t.cell_neighbors(c)) for c in t.cells()) == [1, 1, 2]
    assert t.validate()[0]


def test_errors_name_the_label_and_value():
    a = np.array([[2, 2, 3], [3, 3, 3], [2, 2, 3]], dtype=np.int32)
    with pytest.raises(tessella.InputError, match=r"label 2 is made of 2 disconnected pieces"):
        tessella.tissue_from_label_image(a)
    assert labels_of(tessella.tissue_from_label_image(a, keep_pieces=True)) == [2, 2, 3]
    with pytest.raises(tessella.InputError, match=r"dtype float64 is not an integer type"):
        tessella.tissue_from_label_image(a.astype(float))
    with pytest.raises(tessella.InputError, match=r"voxel_size x = 0 must be a positive"):
        tessella.tissue_from_label_image(a, voxel_size=(0, 1), keep_pieces=True)
    with pytest.raises(tessella.InputError, match=r"one label only \(4 in every pixel\)"):
        tessella.tissue_from_label_image(np.full((4, 4), 4))
    with pytest.raises(tessella.InputError, match=r"needs voxel_size of 3 numbers \(x, y, z\), got 2"):
        tessella.tissue_from_label_image(np.stack([a, a]), voxel_size=(1, 1), keep_pieces=True)
    # One z layer is a 2D image.
    assert tessella.tissue_from_label_image(a[np.newaxis], keep_pieces=True).num_cells == 3


def point_in_polygon(poly, x, y):
    inside = np.zeros(x.shape, dtype=bool)
    n = len(poly)
    for i in range(n):
        (x1, y1), (x2, y2) = poly[i], poly[i - 1]
        crosses = (y1 > y) != (y2 > y)
        with np.errstate(divide="ignore", invalid="ignore"):
            xint = (x2 - x1) * (y - y1) / (y2 - y1) + x1
        inside ^= crosses & (x < xint)
    return inside


def rasterise(t, n):
    """n x n pixels over the unit square: the label (cell + 2) of the cell holding each pixel centre."""
    centres = (np.arange(n) + 0.5) / n
    x, y = np.meshgrid(centres, centres)  # [y, x]
    image = np.zeros((n, n), dtype=np.int32)
    pos = t.positions()
    for c in t.cells():
        poly = pos[t.cell_vertices(c)][:, :2]
        image[point_in_polygon(poly, x, y)] = c + 2
    return image


def neighbour_pairs(t, labels):
    pairs = set()
    for w in t.walls():
        cells = t.wall_cells(w)
        if len(cells) == 2:
            pairs.add(tuple(sorted((labels[cells[0]], labels[cells[1]]))))
    return pairs


def test_rasterised_voronoi_tissue_through_a_tiff_file(tmp_path):
    square = tessella.Rectangle(min=[0, 0, 0], max=[1, 1, 0])
    original = tessella.voronoi_tissue(tessella.random_seeds(square, 200, rng_seed=7), square, lloyd_iterations=10)
    n = 512
    image = rasterise(original, n)
    assert (image >= 2).all()
    # Written by Pillow (not VTK): row 0 of the array is the file's first row.
    path = tmp_path / "cells.tif"
    Image.fromarray(image.astype(np.uint16)).save(path)
    from_file = tessella.tissue_from_label_image(path, voxel_size=(1 / n, 1 / n), simplify=1.0)
    from_array = tessella.tissue_from_label_image(image, voxel_size=(1 / n, 1 / n), simplify=1.0)
    via_import = tessella.import_tissue(str(path))  # default options: pixel size 1, origin 0
    for t in (from_file, from_array, via_import):
        assert t.validate()[0]
        assert t.num_cells == 200
    # The file's origin is 0 (the first pixel's centre), the array's default half a pixel.
    np.testing.assert_allclose(from_file.positions()[:, :2] + 0.5 / n, from_array.positions()[:, :2], atol=1e-12)
    np.testing.assert_array_equal(via_import.positions(), tessella.tissue_from_label_image(path).positions())
    # Adjacency as in the original but for walls shorter than 3 pixels; areas close.
    want = neighbour_pairs(original, [c + 2 for c in range(original.num_cells)])
    got = neighbour_pairs(from_array, labels_of(from_array))
    pos = original.positions()
    short = set()
    for w in original.walls():
        cells = original.wall_cells(w)
        vs = original.cell_vertices(cells[0])
        if len(cells) == 2:
            shared = [v for v in vs if v in set(original.cell_vertices(cells[1]))]
            if len(shared) == 2 and np.linalg.norm(pos[shared[0]] - pos[shared[1]]) < 3 / n:
                short.add(tuple(sorted((cells[0] + 2, cells[1] + 2))))
    assert want - got <= short
    assert len(got - want) <= len(short)
    areas = dict(zip(labels_of(from_array), from_array.cell_measures()))
    err = [abs(areas[c + 2] - a) / a for c, a in zip(original.cells(), original.cell_measures())]
    assert np.mean(err) < 0.02


def test_random_label_images_give_valid_tissues_or_a_hole_error():
    # Small noisy images: pieces, diagonal contacts and checkerboards everywhere.
    rng = np.random.default_rng(0)
    outcomes = {"valid": 0, "hole": 0}
    for _ in range(400):
        a = rng.integers(0, rng.integers(2, 6), size=(rng.integers(2, 12), rng.integers(2, 12)))
        if len(np.unique(a)) < 2:
            continue
        for simplify in (0.0, 1.0, 3.0):
            try:
                t = tessella.tissue_from_label_image(a, keep_pieces=True, background=[0], simplify=simplify)
            except tessella.InputError as e:
                assert "has a hole: it surrounds" in str(e) or "no cells" in str(e), str(e)
                outcomes["hole"] += 1
                continue
            ok, message = t.validate()
            assert ok, (a, simplify, message)
            outcomes["valid"] += 1
            assert sorted(set(labels_of(t))) == sorted(set(np.unique(a)) - {0})
    assert outcomes["valid"] > 500


def test_the_bundled_label_image_is_what_its_script_writes(source_dir, tmp_path):
    import subprocess
    import sys
    out = tmp_path / "cells_2d.tif"
    subprocess.run([sys.executable, str(source_dir / "scripts" / "make_label_image.py"), str(out)], check=True)
    assert out.read_bytes() == (source_dir / "configs" / "label_images" / "cells_2d.tif").read_bytes()
    t, report = tessella.tissue_from_label_image_with_report(out, voxel_size=(0.5, 0.5), min_cell_size=20,
                                                             small_cells="merge", simplify=1.0)
    assert t.validate()[0]
    # The specks (labels 500..502) went to the cells around them.
    assert not {500, 501, 502} & set(labels_of(t))
    assert sum("merged into" in note for note in report["notes"]) >= 3


def test_the_bundled_3d_label_image_is_what_its_script_writes(source_dir, tmp_path):
    import subprocess
    import sys
    out = tmp_path / "cells_3d.mha"
    subprocess.run([sys.executable, str(source_dir / "scripts" / "make_label_image.py"), "--3d", str(out)],
                   check=True)
    assert out.read_bytes() == (source_dir / "configs" / "label_images" / "cells_3d.mha").read_bytes()
    t, report = tessella.tissue_from_label_image_with_report(out, min_cell_size=50, small_cells="merge")
    assert t.validate()[0]
    # One cell per seed of the script (labels 2..19); the specks (500, 501) went to the cells around them.
    assert sorted(set(labels_of(t))) == list(range(2, 20))
    assert sum("merged into" in note for note in report["notes"]) == 2


def shared_wall_lengths(t, labels, positions=None):
    """{(label a, label b): length of the walls they share}, from consecutive shared vertices of a's loop."""
    pos = t.positions() if positions is None else positions
    loops = {c: list(t.cell_vertices(c)) for c in t.cells()}
    out = {}
    for c in t.cells():
        loop = loops[c]
        for n in t.cell_neighbors(c):
            if n < c:
                continue
            other = set(loops[n])
            length = sum(np.linalg.norm(pos[u] - pos[v]) for u, v in zip(loop, loop[1:] + loop[:1])
                         if u in other and v in other)
            out[tuple(sorted((labels[c], labels[n])))] = length
    return out


def test_a_real_meristem_projected_and_rasterised_keeps_its_cell_graph(source_dir):
    # The MorphoGraphX meristem (128 cells, a curved L1 sheet), projected onto its best-fit plane and
    # rasterised by label at 0.05 um per pixel (1478 x 1243): every cell lies inside the image, and the
    # neighbour pairs (those of the MorphoGraphX cell graph: tests/sim/test_real_meristem.cpp) come back.
    mesh = source_dir / "tests" / "data" / "mgx_meristem_cropped" / "mesh_meristem_cropped_T0.ply"
    sheet = tessella.import_tissue(str(mesh))
    sheet_labels = labels_of(sheet)
    p = sheet.positions()
    _, _, axes = np.linalg.svd(p - p.mean(axis=0))
    flat = (p - p.mean(axis=0)) @ axes[:2].T
    h = 0.05
    lo = flat.min(axis=0) - 2 * h
    nx, ny = (np.ceil((flat.max(axis=0) + 2 * h - lo) / h)).astype(int)
    image = np.zeros((ny, nx), dtype=np.int32)
    xs = lo[0] + (np.arange(nx) + 0.5) * h
    ys = lo[1] + (np.arange(ny) + 0.5) * h
    for c in sheet.cells():
        poly = flat[sheet.cell_vertices(c)]
        i0, j0 = np.floor((poly.min(axis=0) - lo) / h).astype(int)
        i1, j1 = np.ceil((poly.max(axis=0) - lo) / h).astype(int) + 1
        x, y = np.meshgrid(xs[i0:i1], ys[j0:j1])
        block = image[j0:j1, i0:i1]
        block[point_in_polygon(poly, x, y)] = sheet_labels[c]
    # MorphoGraphX labels start at 1: only 0 is background here.
    t = tessella.tissue_from_label_image(image, voxel_size=(h, h), simplify=1.0, background=[0])
    assert t.validate()[0]
    assert sorted(labels_of(t)) == sorted(sheet_labels)
    flat3 = np.column_stack([flat, np.zeros(len(flat))])
    want = shared_wall_lengths(sheet, sheet_labels, flat3)
    got = shared_wall_lengths(t, labels_of(t))
    assert len(want) == 340  # the cell graph's neighbour pairs at T0
    # At this resolution the shortest wall spans enough pixels: the same pairs exactly.
    assert min(want.values()) > 3 * h
    assert set(got) == set(want)


def test_3d_array_of_boxes_has_exact_volumes():
    # Two labels side by side in a [z, y, x] array: 3 layers, 2 rows, 1 + 3 columns.
    a = np.zeros((3, 2, 4), dtype=np.uint16)
    a[:, :, 0:1] = 5
    a[:, :, 1:4] = 7
    t, report = tessella.tissue_from_label_image_with_report(a, voxel_size=(0.5, 2.0, 3.0))
    assert t.dim == 3 and report["file_faces"] == 24
    assert labels_of(t) == [5, 7]
    voxel = 0.5 * 2.0 * 3.0
    np.testing.assert_allclose(t.cell_measures(), [6 * voxel, 18 * voxel], rtol=1e-12)
    # The image spans [0, 4 * 0.5] x [0, 2 * 2] x [0, 3 * 3].
    p = t.positions()
    np.testing.assert_allclose(p.min(axis=0), [0, 0, 0], atol=1e-12)
    np.testing.assert_allclose(p.max(axis=0), [2.0, 4.0, 9.0], atol=1e-12)
    assert t.validate()[0]
    with pytest.raises(tessella.InputError, match=r"voxel_size z = 0 must be a positive"):
        tessella.tissue_from_label_image(a, voxel_size=(1, 1, 0))


def test_3d_voronoi_array_imports_with_its_adjacency():
    # Voxels labelled by the nearest seed (the Voronoi cells), imported back.
    box = tessella.Box(min=[0, 0, 0], max=[1, 1, 1])
    seeds = tessella.random_seeds(box, 30, rng_seed=3)
    original = tessella.voronoi_tissue(seeds, box)
    n = 32
    c = (np.arange(n) + 0.5) / n
    z, y, x = np.meshgrid(c, c, c, indexing="ij")
    points = np.stack([x, y, z], axis=-1)
    d2 = ((points[..., np.newaxis, :] - np.asarray(seeds)) ** 2).sum(axis=-1)
    image = d2.argmin(axis=-1).astype(np.int32) + 2  # [z, y, x]
    t = tessella.tissue_from_label_image(image, voxel_size=(1 / n, 1 / n, 1 / n), simplify=1.0)
    assert t.dim == 3 and t.num_cells == 30 and t.validate()[0]
    assert sorted(labels_of(t)) == list(range(2, 32))
    want = neighbour_pairs(original, [i + 2 for i in range(original.num_cells)])
    got = neighbour_pairs(t, labels_of(t))
    # Pairs may differ only where the original wall is a few voxel faces at most.
    wall_area = {}
    for w in original.walls():
        area = original.wall_measure(w)
        cells = original.wall_cells(w)
        if len(cells) == 2:
            key = tuple(sorted((cells[0] + 2, cells[1] + 2)))
            wall_area[key] = wall_area.get(key, 0) + area
    for pair in want - got:
        assert wall_area[pair] < 4 / n**2, pair
    volumes = dict(zip(labels_of(t), t.cell_measures()))
    err = [abs(volumes[i + 2] - v) / v for i, v in zip(original.cells(), original.cell_measures())]
    assert np.mean(err) < 0.1
    np.testing.assert_allclose(sum(volumes.values()), 1.0, rtol=0.02)


def test_random_3d_label_images_give_valid_tissues_or_a_clear_error():
    # Small noisy volumes: every defect the voxel grid can hold, fixed or refused with a message.
    rng = np.random.default_rng(1)
    valid = 0
    for _ in range(150):
        shape = tuple(rng.integers(2, 7, size=3))
        a = rng.integers(0, rng.integers(2, 5), size=shape)
        if len(np.unique(a)) < 2:
            continue
        for simplify in (0.0, 1.0):
            try:
                t = tessella.tissue_from_label_image(a, keep_pieces=True, background=[0], simplify=simplify)
            except tessella.InputError as e:
                assert "drawn" not in str(e) and "internal error" not in str(e), str(e)
                continue
            # Background voxels may make tunnels and cavities through the tissue: no Euler check then.
            ok, message = t.validate(check_euler=False)
            assert ok, (a, simplify, message)
            valid += 1
            assert sorted(set(labels_of(t))) <= sorted(set(np.unique(a)) - {0})
    assert valid > 0


def write_metaimage(path, a):
    """A [z, y, x] uint16 array as an uncompressed MetaImage file (no spacing given)."""
    header = (f"ObjectType = Image\nNDims = 3\nDimSize = {a.shape[2]} {a.shape[1]} {a.shape[0]}\n"
              "BinaryData = True\nBinaryDataByteOrderMSB = False\nElementType = MET_USHORT\n"
              "ElementDataFile = LOCAL\n")
    with open(path, "wb") as f:
        f.write(header.encode())
        f.write(np.ascontiguousarray(a, dtype="<u2").tobytes())


def test_3d_image_from_yaml_takes_three_voxel_sizes(tmp_path):
    # tissue.import.voxel_size takes [x, y, z] for a 3D image; the volumes follow it.
    a = np.zeros((3, 2, 4), dtype=np.uint16)
    a[:, :, 0:1] = 5
    a[:, :, 1:4] = 7
    write_metaimage(tmp_path / "boxes.mha", a)
    config = (f"tissue:\n  generator: import\n  import:\n    file: {tmp_path / 'boxes.mha'}\n"
              "    voxel_size: [0.5, 2.0, 3.0]\ntime:\n  end: 1.0\n  dt: 1.0\n")
    sim = tessella.Simulation.from_yaml(config)
    voxel = 0.5 * 2.0 * 3.0
    np.testing.assert_allclose(sorted(sim.tissue.cell_measures()), [6 * voxel, 18 * voxel], rtol=1e-12)
    # Two numbers for a 3D image: the importer's error, naming the file and the sizes.
    with pytest.raises(Exception, match=r"boxes\.mha.*(3D|three|voxel)"):
        tessella.Simulation.from_yaml(config.replace("[0.5, 2.0, 3.0]", "[0.5, 2.0]"))
    # Four numbers: the schema's error at the key.
    with pytest.raises(Exception, match=r"voxel_size.*2 or 3 numbers"):
        tessella.Simulation.from_yaml(config.replace("[0.5, 2.0, 3.0]", "[0.5, 2.0, 3.0, 4.0]"))
