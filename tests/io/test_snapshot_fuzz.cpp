// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Seeded fuzzing of the snapshot reader: small 2D and 3D snapshots are
// damaged (bit flips and overwrites in the XML header and in the appended
// binary data, truncations, swapped attribute values, deleted lines, damaged
// block headers) and read back. Every case must end in an InputError naming
// the file, or in a load equal to the intact file's; never a signal, another
// exception or a hang. Each case runs in a forked child, so that a crash is
// reported as a failure naming the case instead of ending the test runner.
//
// TESSELLA_FUZZ_SEED=<n> changes the seed, TESSELLA_FUZZ_CASES=<n> the number
// of cases per snapshot (default 80, 3 snapshots); a failure names the seed,
// the case and the mutation, so that it can be replayed.

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <omp.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "file_edits.hpp"
#include "io_test_support.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/generators/grids.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::TempDir;
using tessella::io::testing::readBytes;
using tessella::io::testing::writeBytes;

namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

template <typename T>
bool sameColumn(const PropertyColumnBase& a, const PropertyColumnBase& b) {
  const auto& va = static_cast<const PropertyColumn<T>&>(a).values();
  const auto& vb = static_cast<const PropertyColumn<T>&>(b).values();
  if (va.size() != vb.size()) return false;
  for (std::size_t i = 0; i < va.size(); ++i)
    if (std::memcmp(&va[i], &vb[i], sizeof(T)) != 0) return false;
  return true;
}

template <typename... Ts>
std::string columnDifference(const PropertyColumnBase& a, const PropertyColumnBase& b) {
  if (a.type() != b.type()) return "property '" + a.name() + "' changed type";
  if (a.policy() != b.policy()) return "property '" + a.name() + "' changed policy";
  bool known = false, same = false;
  ((a.type() == typeid(Ts) ? (known = true, same = sameColumn<Ts>(a, b)) : false) || ...);
  if (!known) return "property '" + a.name() + "' has a type this test cannot compare";
  return same ? "" : "property '" + a.name() + "' has other values";
}

/// The first difference between two tissues read from snapshots, or "" if
/// they are equal: positions bit for bit, cells, lineage, every property.
std::string difference(const Tissue& a, const Tissue& b) {
  if (a.dim() != b.dim() || a.embedding() != b.embedding()) return "dimension or embedding";
  if (!sameBits(a.time(), b.time())) return "time";
  if (a.numVertices() != b.numVertices() || a.numEdges() != b.numEdges() || a.numFaces() != b.numFaces() ||
      a.numCells() != b.numCells())
    return "element counts";
  for (std::size_t i = 0; i < a.numVertices(); ++i)
    if (std::memcmp(a.positions()[i].data(), b.positions()[i].data(), 3 * sizeof(double)) != 0)
      return "position of vertex " + std::to_string(i);
  const CellComplex &ta = a.topology(), &tb = b.topology();
  for (std::size_t f = 0; f < a.numFaces(); ++f) {
    const auto la = ta.faceVertices(FaceId(static_cast<Index>(f))), lb = tb.faceVertices(FaceId(static_cast<Index>(f)));
    if (!std::equal(la.begin(), la.end(), lb.begin(), lb.end())) return "vertex loop of face " + std::to_string(f);
  }
  if (a.dim() == 3)
    for (std::size_t c = 0; c < a.numCells(); ++c) {
      const auto fa = ta.volumeFaces(VolumeId(static_cast<Index>(c))), fb = tb.volumeFaces(VolumeId(static_cast<Index>(c)));
      if (!std::equal(fa.begin(), fa.end(), fb.begin(), fb.end(), [](OrientedFace x, OrientedFace y) {
            return x.handle() == y.handle() && x.reversed() == y.reversed();
          }))
        return "faces of cell " + std::to_string(c);
    }
  for (std::size_t c = 0; c < a.numCells(); ++c) {
    const CellId id(static_cast<Index>(c));
    if (a.lineageId(id) != b.lineageId(id) || a.parentId(id) != b.parentId(id) ||
        !sameBits(a.birthTime(id), b.birthTime(id)))
      return "lineage of cell " + std::to_string(c);
  }
  if (a.nextLineageId() != b.nextLineageId()) return "next lineage id";
  for (int degree : {0, a.dim()}) {
    const PropertyStore &sa = a.properties(degree), &sb = b.properties(degree);
    if (sa.names() != sb.names()) return "property names of degree " + std::to_string(degree);
    for (std::size_t i = 0; i < sa.numColumns(); ++i) {
      const std::string d =
          columnDifference<double, float, std::int8_t, std::uint8_t, std::int16_t, std::uint16_t, std::int32_t,
                           std::uint32_t, std::int64_t, std::uint64_t, Vec3, Eigen::Vector2d, Sym3, Mat3>(
              sa.column(i), *sb.find(sa.column(i).name()));
      if (!d.empty()) return d;
    }
  }
  return "";
}

struct Outcome {
  bool ok = false;
  std::string what;  // the failure, or how the case ended
};

/// Reads `path` in a forked child and classifies the end: an InputError
/// naming the file or a load equal to `reference` is ok; a signal, another
/// exception, an InputError without the path, a different load or a run over
/// `timeout_s` is not.
Outcome readInChild(const std::string& path, const Tissue& reference, unsigned timeout_s) {
  int fds[2];
  REQUIRE(pipe(fds) == 0);
  std::fflush(nullptr);
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    close(fds[0]);
    // Catch's crash handlers must not report from the child: it just dies.
    for (int sig : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGALRM}) std::signal(sig, SIG_DFL);
    const rlimit no_core{0, 0};
    setrlimit(RLIMIT_CORE, &no_core);
    // A corrupted size must not take the machine's memory: 4 GiB more than now.
    rlimit as{};
    getrlimit(RLIMIT_AS, &as);
    long pages = 0;
    if (std::ifstream statm("/proc/self/statm"); statm >> pages) {
      const rlim_t limit = static_cast<rlim_t>(pages) * static_cast<rlim_t>(sysconf(_SC_PAGESIZE)) + (rlim_t{4} << 30);
      if (as.rlim_max == RLIM_INFINITY || limit < as.rlim_max) as.rlim_cur = limit;
      setrlimit(RLIMIT_AS, &as);
    }
    // libgomp's thread pool does not survive fork(): a parallel region with
    // more than one thread would wait for the parent's threads forever.
    omp_set_num_threads(1);
    alarm(timeout_s);
    std::string report;
    try {
      const Tissue t = readTissueVtu(path);
      const std::string d = difference(reference, t);
      report = d.empty() ? "+loaded, equal to the original" : "-loaded, but differs from the original: " + d;
    } catch (const InputError& e) {
      const std::string what = e.what();
      report = what.find(path) != std::string::npos ? "+InputError: " + what
                                                    : "-InputError that does not name the file: " + what;
    } catch (const std::exception& e) {
      report = std::string("-exception other than InputError (") + typeid(e).name() + "): " + e.what();
    }
    const char* p = report.data();
    std::size_t left = report.size();
    while (left > 0) {
      const ssize_t n = write(fds[1], p, left);
      if (n <= 0) break;
      p += n, left -= static_cast<std::size_t>(n);
    }
    _exit(0);
  }
  close(fds[1]);
  std::string report;
  char buffer[4096];
  for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    report.append(buffer, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    return {false, sig == SIGALRM ? "did not finish within " + std::to_string(timeout_s) + " s"
                                  : "signal " + std::to_string(sig) + " (" + strsignal(sig) + ")"};
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || report.empty())
    return {false, "the child ended without a report (status " + std::to_string(status) + ")"};
  return {report[0] == '+', report.substr(1)};
}

/// Where the XML header ends and the appended binary data begin.
struct Layout {
  std::size_t data_start = 0;  // first byte after the '_' that opens the appended data
  std::vector<std::size_t> offsets;  // offset="..." values (relative to data_start)
};

Layout layoutOf(const std::string& bytes) {
  Layout l;
  const auto appended = bytes.find("<AppendedData");
  REQUIRE(appended != std::string::npos);
  const auto underscore = bytes.find('_', appended);
  REQUIRE(underscore != std::string::npos);
  l.data_start = underscore + 1;
  const std::string header = bytes.substr(0, appended);
  static const std::regex offset_re("offset=\"([0-9]+)\"");
  for (std::sregex_iterator it(header.begin(), header.end(), offset_re), end; it != end; ++it)
    l.offsets.push_back(std::stoull((*it)[1].str()));
  return l;
}

/// Replacement values worth trying for an attribute.
std::vector<std::string> candidates(const std::string& attribute, const std::string& value) {
  const std::vector<std::string> numbers = {"0", "1", "-1", "2", "3", "7", "9", "-2147483648", "2147483647",
                                            "4294967297", "9223372036854775807", "18446744073709551615",
                                            "1e18", "abc", "", "1.5"};
  if (attribute == "type")
    return {"Int8", "UInt8", "Int16", "UInt16", "Int32", "UInt32", "Int64", "UInt64", "Float32", "Float64",
            "String", "Xtring", "Bit", "IdType", "UnstructuredGrid", "PolyData", "ImageData", ""};
  if (attribute == "header_type") return {"UInt32", "UInt64", "Int32", "UInt8", "Float64", "UInt16", ""};
  if (attribute == "format") return {"ascii", "binary", "appended", "", "raw"};
  if (attribute == "compressor")
    return {"vtkZLibDataCompressor", "vtkLZ4DataCompressor", "vtkLZMADataCompressor", "", "vtkNoSuchCompressor"};
  if (attribute == "byte_order") return {"BigEndian", "LittleEndian", ""};
  if (attribute == "encoding") return {"raw", "base64", ""};
  if (attribute == "version") return {"0.1", "1.0", "2.2", "", "x"};
  if (attribute == "Name")
    return {"Points", "connectivity", "offsets", "types", "faces", "faceoffsets", "area", "lineage", "", "x"};
  std::vector<std::string> out = numbers;
  if (!value.empty() && value.find_first_not_of("0123456789") == std::string::npos) {
    const long long v = std::stoll(value);
    for (long long d : {-8LL, -1LL, 1LL, 8LL, 1024LL}) out.push_back(std::to_string(v + d));
    out.push_back(std::to_string(v * 2));
  }
  return out;
}

/// One mutation of `bytes`, chosen by `rng`; returns its description.
std::string mutate(std::string& bytes, std::mt19937_64& rng) {
  const Layout layout = layoutOf(bytes);
  const std::size_t header_size = layout.data_start, data_size = bytes.size() - layout.data_start;
  const auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % std::max<std::size_t>(n, 1)); };
  switch (pick(9)) {
    case 0: {  // a bit flip in the header
      const std::size_t at = pick(header_size);
      const int bit = static_cast<int>(pick(8));
      bytes[at] = static_cast<char>(bytes[at] ^ (1 << bit));
      return "flip bit " + std::to_string(bit) + " of header byte " + std::to_string(at);
    }
    case 1: {  // a byte of the header overwritten
      const std::size_t at = pick(header_size);
      const char by = "\"<>= /_0123456789azAZ\n\xff"[pick(24)];
      bytes[at] = by;
      return "header byte " + std::to_string(at) + " := " + std::to_string(static_cast<unsigned char>(by));
    }
    case 2: {  // a bit flip in the binary data
      const std::size_t at = layout.data_start + pick(data_size);
      const int bit = static_cast<int>(pick(8));
      bytes[at] = static_cast<char>(bytes[at] ^ (1 << bit));
      return "flip bit " + std::to_string(bit) + " of data byte " + std::to_string(at - layout.data_start);
    }
    case 3: {  // a byte of the binary data overwritten
      const std::size_t at = layout.data_start + pick(data_size);
      const auto by = static_cast<unsigned char>(pick(256));
      bytes[at] = static_cast<char>(by);
      return "data byte " + std::to_string(at - layout.data_start) + " := " + std::to_string(by);
    }
    case 4: {  // truncation
      const std::size_t size = pick(bytes.size());
      bytes.resize(size);
      return "truncated to " + std::to_string(size) + " bytes";
    }
    case 5:
    case 6: {  // an attribute value swapped
      static const std::regex attr_re("([A-Za-z_]+)=\"([^\"]*)\"");
      const std::string header = bytes.substr(0, header_size);
      std::vector<std::smatch> found;
      for (std::sregex_iterator it(header.begin(), header.end(), attr_re), end; it != end; ++it) found.push_back(*it);
      if (found.empty()) return "no attribute to swap";
      const std::smatch& m = found[pick(found.size())];
      const std::string attribute = m[1].str(), value = m[2].str();
      const auto options = candidates(attribute, value);
      const std::string replacement = options[pick(options.size())];
      bytes.replace(static_cast<std::size_t>(m.position(2)), value.size(), replacement);
      return attribute + "=\"" + value + "\" -> \"" + replacement + "\" at byte " + std::to_string(m.position(2));
    }
    case 7: {  // a header line deleted
      std::vector<std::size_t> starts{0};
      for (std::size_t i = 0; i < header_size; ++i)
        if (bytes[i] == '\n') starts.push_back(i + 1);
      const std::size_t line = pick(starts.size() - 1);
      bytes.erase(starts[line], starts[line + 1] - starts[line]);
      return "deleted header line " + std::to_string(line + 1);
    }
    default: {  // a block header word of an array's data overwritten
      if (layout.offsets.empty()) return "no array offsets";
      const std::size_t offset = layout.offsets[pick(layout.offsets.size())];
      const std::size_t word = pick(4);
      const std::size_t at = layout.data_start + offset + 8 * word;
      const std::uint64_t values[] = {0, 1, 2, 7, 0xffffffffull, 0x100000000ull, 0x7fffffffffffffffull,
                                      ~std::uint64_t{0}, 1ull << 40, 65536, 32768, 3};
      const std::uint64_t v = values[pick(std::size(values))];
      if (at + 8 > bytes.size()) return "block header past the end";
      std::memcpy(bytes.data() + at, &v, 8);
      return "block header word " + std::to_string(word) + " of the array at offset " + std::to_string(offset) +
             " := " + std::to_string(v);
    }
  }
}

std::uint64_t envNumber(const char* name, std::uint64_t fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::strtoull(v, nullptr, 10) : fallback;
}

Tissue withProperties(Tissue t) {
  auto& growth = t.cellProperties().add<double>("growth", 0.5, DivisionPolicy::SplitByMeasure);
  auto& label = t.cellProperties().add<std::int32_t>("label", 7, DivisionPolicy::Reset);
  auto& direction = t.cellProperties().add<Vec3>("direction", Vec3::UnitX());
  auto& auxin = t.properties(0).add<float>("auxin", 0.0f);
  Index i = 0;
  for (CellId c : t.cells()) {
    growth[c] = 0.1 * i + 1.0 / 3.0;
    label[c] = static_cast<std::int32_t>(100 - i);
    direction[c] = Vec3(static_cast<double>(i), 1.0 / (i + 1.0), -0.25 * i);
    ++i;
  }
  for (VertexId v : t.vertices()) auxin[v] = 0.5f * static_cast<float>(v.index()) + 0.125f;
  t.setTime(2.75);
  return t;
}

}  // namespace

TEST_CASE("damaged snapshots end in an InputError naming the file or an equal load, never a crash",
          "[io][vtu][errors][fuzz]") {
  const std::uint64_t seed = envNumber("TESSELLA_FUZZ_SEED", 20240620);
  const std::uint64_t cases = envNumber("TESSELLA_FUZZ_CASES", 80);
  struct Snapshot {
    std::string name;
    Tissue tissue;
    Compression compression;
  };
  const std::vector<Snapshot> snapshots = {
      {"2d-lz4", withProperties(rectangularGrid(3, 2)), Compression::LZ4},
      {"2d-raw", withProperties(hexagonalGrid(2, 2)), Compression::None},
      {"3d-zlib", withProperties(boxGrid(2, 1, 1)), Compression::ZLib},
  };
  TempDir dir;
  std::vector<std::string> failures;
  std::size_t refused = 0, loaded = 0;
  for (std::size_t s = 0; s < snapshots.size(); ++s) {
    const Snapshot& snap = snapshots[s];
    const std::string original = dir.file(snap.name + ".vtu");
    VtuOptions options;
    options.compression = snap.compression;
    writeTissueVtu(snap.tissue, original, options);
    const Tissue reference = readTissueVtu(original);
    tessella::io::testing::requireSameTissue(snap.tissue, reference);
    const std::string bytes = readBytes(original);
    for (std::uint64_t k = 0; k < cases; ++k) {
      std::mt19937_64 rng(seed * 1000003u + s * 10007u + k);
      std::string damaged = bytes;
      const std::string mutation = mutate(damaged, rng);
      const std::string path = dir.file(snap.name + "-case" + std::to_string(k) + ".vtu");
      writeBytes(path, damaged);
      const Outcome outcome = readInChild(path, reference, 60);
      const std::string name =
          "seed " + std::to_string(seed) + " " + snap.name + " case " + std::to_string(k) + " (" + mutation + ")";
      if (!outcome.ok) failures.push_back(name + ": " + outcome.what);
      else if (outcome.what.rfind("InputError", 0) == 0) ++refused;
      else ++loaded;
      std::filesystem::remove(path);
    }
  }
  INFO(refused << " cases refused, " << loaded << " loaded equal to the original, " << failures.size() << " failed");
  std::ostringstream all;
  for (const std::string& f : failures) all << f << "\n";
  INFO(all.str());
  CHECK(failures.empty());
  // The mutations must hit: most damaged files are refused.
  CHECK(refused > loaded);
}
