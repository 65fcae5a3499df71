#include "atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
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
  if (fd < 0) throw InputError("cannot open '" + path + "' to flush it to disk");
  const int rc = ::fsync(fd);
  ::close(fd);
  if (rc != 0) throw InputError("cannot flush '" + path + "' to disk");
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
