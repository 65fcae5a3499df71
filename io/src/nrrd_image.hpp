// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// NRRD label images (.nrrd, .nhdr), read without vtkNrrdReader: VTK 9.1's reader takes a first axis of 9
// or fewer samples for pixel components, which crashes it (SIGSEGV) when one axis is left and reads any
// other such image as a colour image; it reads ASCII 8-bit values as characters. The header is parsed
// here, strictly; raw data is read by VTK's vtkImageReader2, gzip and ASCII data here (docs/import.md).

#include <string>

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

namespace tessella::io::detail {

/// The image of the NRRD file `path` (attached data or a detached header naming one data file): its
/// sizes, spacing, origin and one integer scalar per pixel, in the order stored (x fastest). Throws
/// InputError naming the file, the field and its value for anything malformed or not a label image.
vtkSmartPointer<vtkImageData> readNrrdImage(const std::string& path);

}  // namespace tessella::io::detail
