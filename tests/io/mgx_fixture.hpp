// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// MorphoGraphX-style cell meshes for the import tests (and bench/import_bench):
// an nx x ny grid of square cells on a gently curved sheet, each cell a fan of
// triangles around its own centre vertex, its walls subdivided into `k`
// segments and shared with its neighbours, written as MorphoGraphX writes
// them (vertex: x y z label signal parent cellNr; face: vertex_index label).

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "tessella/tissue/vec3.hpp"

namespace tessella::io::testing {

struct MgxFixture {
  std::vector<Vec3> positions;
  std::vector<int> vertex_label;   // -1 on walls, the cell's label at its centre
  std::vector<int> vertex_parent;  // 0 on walls
  std::vector<std::vector<int>> faces;
  std::vector<int> face_label;

  /// Cell (i, j) has label 10 + i + nx * j and parent 1000 + that label.
  static MgxFixture grid(int nx, int ny, int k, double curvature = 0.02) {
    MgxFixture m;
    const int wx = nx * k + 1, wy = ny * k + 1;
    std::vector<int> lattice(static_cast<std::size_t>(wx) * wy, -1);
    auto at = [&](int a, int b) -> int {
      int& id = lattice[static_cast<std::size_t>(b) * wx + a];
      if (id < 0) id = m.addVertex(double(a) / k, double(b) / k, curvature, -1, 0);
      return id;
    };
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int label = 10 + i + nx * j;
        std::vector<int> loop;  // counter-clockwise seen from +z
        for (int s = 0; s < k; ++s) loop.push_back(at(i * k + s, j * k));
        for (int s = 0; s < k; ++s) loop.push_back(at((i + 1) * k, j * k + s));
        for (int s = 0; s < k; ++s) loop.push_back(at((i + 1) * k - s, (j + 1) * k));
        for (int s = 0; s < k; ++s) loop.push_back(at(i * k, (j + 1) * k - s));
        const int centre = m.addVertex(i + 0.5, j + 0.5, curvature, label, 1000 + label);
        for (std::size_t q = 0; q < loop.size(); ++q) {
          m.faces.push_back({centre, loop[q], loop[(q + 1) % loop.size()]});
          m.face_label.push_back(label);
        }
      }
    return m;
  }

  int addVertex(double x, double y, double curvature, int label, int parent) {
    positions.emplace_back(x, y, curvature * (x * x + y * y));
    vertex_label.push_back(label);
    vertex_parent.push_back(parent);
    return static_cast<int>(positions.size()) - 1;
  }

  /// Faces of a label.
  std::vector<std::size_t> facesOf(int label) const {
    std::vector<std::size_t> out;
    for (std::size_t f = 0; f < faces.size(); ++f)
      if (face_label[f] == label) out.push_back(f);
    return out;
  }

  /// Sum of the areas of a label's triangles (the area MorphoGraphX measures).
  double triangleArea(int label, double scale = 1.0) const {
    double a = 0;
    for (std::size_t f : facesOf(label)) {
      const Vec3 p = positions[faces[f][0]], q = positions[faces[f][1]], r = positions[faces[f][2]];
      a += 0.5 * (q - p).cross(r - p).norm();
    }
    return a * scale * scale;
  }

  enum class Format { Ascii, BinaryLittleEndian, BinaryBigEndian };

  void write(const std::string& path, Format format = Format::Ascii) const {
    std::ofstream out(path, std::ios::binary);
    out << "ply\nformat "
        << (format == Format::Ascii                ? "ascii"
            : format == Format::BinaryLittleEndian ? "binary_little_endian"
                                                   : "binary_big_endian")
        << " 1.0\ncomment Exported from MorphoGraphX (a Tessella test fixture)\nelement vertex " << positions.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nproperty int label\nproperty float signal\n"
           "property int parent\nproperty int cellNr\nelement face "
        << faces.size() << "\nproperty list uchar int vertex_index\nproperty int label\nend_header\n";
    if (format == Format::Ascii) {
      out.precision(9);
      for (std::size_t v = 0; v < positions.size(); ++v)
        out << positions[v].x() << ' ' << positions[v].y() << ' ' << positions[v].z() << ' ' << vertex_label[v]
            << " 0.5 " << vertex_parent[v] << " 0\n";
      for (std::size_t f = 0; f < faces.size(); ++f) {
        out << faces[f].size();
        for (int v : faces[f]) out << ' ' << v;
        out << ' ' << face_label[f] << '\n';
      }
      return;
    }
    const bool swap = (format == Format::BinaryBigEndian) == (std::endian::native == std::endian::little);
    auto put = [&](auto value) {
      char b[sizeof value];
      std::memcpy(b, &value, sizeof value);
      if (swap)
        for (std::size_t i = 0; i < sizeof value / 2; ++i) std::swap(b[i], b[sizeof value - 1 - i]);
      out.write(b, sizeof value);
    };
    for (std::size_t v = 0; v < positions.size(); ++v) {
      put(float(positions[v].x())), put(float(positions[v].y())), put(float(positions[v].z()));
      put(std::int32_t(vertex_label[v])), put(0.5f), put(std::int32_t(vertex_parent[v])), put(std::int32_t(0));
    }
    for (std::size_t f = 0; f < faces.size(); ++f) {
      put(std::uint8_t(faces[f].size()));
      for (int v : faces[f]) put(std::int32_t(v));
      put(std::int32_t(face_label[f]));
    }
  }
};

}  // namespace tessella::io::testing
