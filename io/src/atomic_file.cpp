// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <filesystem>
#include <system_error>

#include "tessella/tissue/errors.hpp"

namespace tessella::io::detail {

namespace fs = std::filesystem;

namespace {

// Unique per process and call, so concurrent writers never share a temporary.
std::string temporaryPathFor(const std::string& path) {
  static std::atomic<unsigned long> counter{0};
  return path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

void syncFile(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) throw InputError("cannot open '" + path + "' to flush it to disk: " + osReason(errno));
  const int rc = ::fsync(fd);
  const int error = errno;
  ::close(fd);
  if (rc != 0) throw InputError("cannot flush '" + path + "' to disk: " + osReason(error));
}

// Makes the rename itself durable.
void syncDirectoryOf(const std::string& path) {
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;  // some file systems do not let directories be opened; the data are synced
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

std::string osReason(int error) { return std::error_code(error, std::generic_category()).message(); }

void writeBytes(const std::string& file, std::string_view data, const std::string& target) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw InputError("cannot write '" + target + "': " + osReason(errno));
  while (!data.empty()) {
    const ssize_t n = ::write(fd, data.data(), data.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : EIO;
      ::close(fd);
      throw InputError("cannot write '" + target + "': " + osReason(error));
    }
    data.remove_prefix(static_cast<std::size_t>(n));
  }
  // close() reports delayed write errors on some file systems (NFS, quotas).
  if (::close(fd) != 0) throw InputError("cannot write '" + target + "': " + osReason(errno));
}

void replaceAtomically(const std::string& path, const std::function<void(const std::string&)>& write,
                       bool durable) {
  const std::string tmp = temporaryPathFor(path);
  try {
    write(tmp);
    if (durable) syncFile(tmp);
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) throw InputError("cannot move the finished file into place as '" + path + "': " + ec.message());
    if (durable) syncDirectoryOf(path);
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
}

}  // namespace tessella::io::detail
