// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Damaging files on purpose, shared by the io tests of bad input: bytes in
// and out, and a snapshot rewritten by VTK alone after an edit of its grid
// (a file Tessella's writer would refuse to produce).

#include <fstream>
#include <iterator>
#include <string>

#include <catch2/catch.hpp>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

namespace tessella::io::testing {

inline std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

inline void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/// Reads a snapshot with VTK, lets `edit` change its grid, writes it back
/// with VTK. The checksum list goes too (as an editing program must remove
/// it), so that the reader's own checks are what finds the damage; unless
/// told to keep it.
template <typename Edit>
void tamper(const std::string& in, const std::string& out, Edit edit, bool keep_checksums = false) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(in.c_str());
  reader->Update();
  vtkNew<vtkUnstructuredGrid> grid;
  grid->DeepCopy(reader->GetOutput());
  edit(grid.Get());
  if (!keep_checksums) grid->GetFieldData()->RemoveArray("tessella_checksums");
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(out.c_str());
  REQUIRE(writer->Write() == 1);
}

/// The snapshot `in` as a file written before snapshots stored the complex's
/// layout: every `tessella_topology:*` field array removed.
inline void withoutLayoutArrays(const std::string& in, const std::string& out) {
  tamper(in, out, [](vtkUnstructuredGrid* grid) {
    vtkFieldData* field = grid->GetFieldData();
    for (int i = field->GetNumberOfArrays() - 1; i >= 0; --i)
      if (std::string(field->GetArrayName(i)).rfind("tessella_topology:", 0) == 0)
        field->RemoveArray(field->GetArrayName(i));
  });
}

}  // namespace tessella::io::testing
