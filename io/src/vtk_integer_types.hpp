// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Which VTK data types hold integers: what a label array or label image must
// be (a float array of labels is refused, not rounded).

#include <vtkType.h>

namespace tessella::io::detail {

inline bool isVtkIntegerType(int vtk_type) {
  switch (vtk_type) {
    case VTK_CHAR: case VTK_SIGNED_CHAR: case VTK_UNSIGNED_CHAR: case VTK_SHORT: case VTK_UNSIGNED_SHORT:
    case VTK_INT: case VTK_UNSIGNED_INT: case VTK_LONG: case VTK_UNSIGNED_LONG: case VTK_LONG_LONG:
    case VTK_UNSIGNED_LONG_LONG: case VTK_ID_TYPE:
      return true;
    default:
      return false;
  }
}

}  // namespace tessella::io::detail
