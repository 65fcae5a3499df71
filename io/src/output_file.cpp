// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/io/output_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "tessella/tissue/errors.hpp"

namespace tessella::io {

void checkOutputFile(const std::string& path, const std::string& label) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.empty()) throw InputError(label + ": the output file name is empty");
  if (fs::is_directory(path, ec)) throw InputError(label + " " + path + ": is a directory");
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  if (!fs::is_directory(dir, ec))
    throw InputError(label + " " + path + ": the directory " + dir.string() +
                     (fs::exists(dir, ec) ? " is not a directory" : " does not exist"));
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw InputError(label + " " + path + ": cannot write into " + dir.string() + ": " + std::strerror(errno));
}

}  // namespace tessella::io
