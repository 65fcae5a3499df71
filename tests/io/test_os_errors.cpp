// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Failed writes and reads say why in the operating system's words ("No such
// file or directory", "File too large"), name the path, carry none of VTK's
// internal dump, and leave no temporary file behind.

#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "io_test_support.hpp"
#include "tessella/io/pvd.hpp"
#include "tessella/io/text_file.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/generators/grids.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::TempDir;
using Catch::Contains;

namespace {

// Limits the size of files this process may write (RLIMIT_FSIZE) while it
// lives: a write past the limit fails with EFBIG, as a full disk fails with
// ENOSPC, without root or a special file system. SIGXFSZ is ignored so that
// the write fails instead of ending the process.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    REQUIRE(::getrlimit(RLIMIT_FSIZE, &saved_) == 0);
    old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = saved_;
    limit.rlim_cur = bytes;
    REQUIRE(::setrlimit(RLIMIT_FSIZE, &limit) == 0);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, old_handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit saved_{};
  void (*old_handler_)(int) = SIG_DFL;
};

// The message of the InputError `f` throws ("" if it throws none).
template <typename F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// What VTK would print about itself: none of it belongs in a message.
void requireNoVtkDump(const std::string& message) {
  INFO(message);
  for (const char* part : {"vtkInformation", "Debug: Off", "0x", "\033["})
    REQUIRE(message.find(part) == std::string::npos);
}

}  // namespace

TEST_CASE("a snapshot into a missing directory names the path and the reason", "[io][vtu][errors][os]") {
  TempDir dir;
  const std::string path = dir.file("missing_dir/snap.vtu");
  const std::string message = errorOf([&] { writeTissueVtu(rectangularGrid(2, 2), path); });
  REQUIRE_THAT(message, Contains("cannot write '" + path + "': No such file or directory"));
  requireNoVtkDump(message);
  REQUIRE(dir.entries().empty());
}

TEST_CASE("a snapshot larger than the file system allows says so and leaves nothing", "[io][vtu][errors][os]") {
  TempDir dir;
  const std::string path = dir.file("big.vtu");
  VtuOptions options;
  options.compression = Compression::None;
  const Tissue big = rectangularGrid(40, 40);
  {
    FileSizeLimit limit(8192);
    const std::string message = errorOf([&] { writeTissueVtu(big, path, options); });
    REQUIRE_THAT(message, Contains("cannot write '" + path + "': File too large"));
    requireNoVtkDump(message);
  }
  REQUIRE(dir.entries().empty());
  writeTissueVtu(big, path, options);  // the limit is gone: the same write succeeds
  REQUIRE(dir.entries() == std::vector<std::string>{"big.vtu"});
}

TEST_CASE("text files and collections report the reason and leave no temporary", "[io][series][errors][os]") {
  TempDir dir;
  const std::string missing = dir.file("missing_dir/run.yaml");
  REQUIRE_THROWS_WITH(writeTextFile(missing, "a: 1\n"),
                      Contains("cannot write '" + missing + "': No such file or directory"));

  const std::string record = dir.file("run.yaml");
  writeTextFile(record, "old: 1\n");
  const std::string pvd = dir.file("s.pvd");
  const std::vector<PvdEntry> entries(200, PvdEntry{1.0, "a_long_file_name_for_every_step.vtu"});
  {
    FileSizeLimit limit(1024);
    REQUIRE_THROWS_WITH(writeTextFile(record, std::string(4096, 'x')),
                        Contains("cannot write '" + record + "': File too large"));
    REQUIRE_THROWS_WITH(writePvdFile(pvd, entries), Contains("cannot write '" + pvd + "': File too large"));
  }
  // The previous run.yaml is untouched, and no temporary is left.
  REQUIRE(dir.entries() == std::vector<std::string>{"run.yaml"});
  REQUIRE(std::filesystem::file_size(record) == 7);
}

TEST_CASE("reading a snapshot without permission gives the reason", "[io][vtu][errors][os]") {
  TempDir dir;
  const std::string path = dir.file("snap.vtu");
  writeTissueVtu(rectangularGrid(2, 2), path);
  std::filesystem::permissions(path, std::filesystem::perms::none);
  if (::geteuid() == 0) {
    WARN("skipped: running as root, which reads files without read permission");
    return;
  }
  const std::string message = errorOf([&] { readTissueVtu(path); });
  REQUIRE_THAT(message, Contains("cannot read '" + path + "': Permission denied"));
  requireNoVtkDump(message);
}
