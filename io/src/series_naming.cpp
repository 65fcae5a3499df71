#include "series_naming.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::io::detail {

void checkSeriesName(const std::string& name) {
  if (name.empty()) throw InputError("series name must not be empty");
  if (name.find_first_of("/\\") != std::string::npos || name == "." || name == "..")
    throw InputError("series name '" + name + "' must not contain a path separator");
}

void createSeriesDirectory(const std::string& directory) {
  if (directory.empty()) throw InputError("series directory must not be empty");
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  if (ec || !std::filesystem::is_directory(directory))
    throw InputError("cannot create the output directory '" + directory + "'" + (ec ? ": " + ec.message() : std::string()));
}

std::string stepFileName(const std::string& name, std::size_t step) {
  char digits[32];
  std::snprintf(digits, sizeof digits, "%06zu", step);
  return name + "_" + digits + ".vtu";
}

void checkNextTime(const std::string& pvd_path, const double* previous, double time) {
  if (!std::isfinite(time))
    throw InputError("'" + pvd_path + "': step time " + formatNumber(time) + " is not finite");
  if (previous && !(time > *previous))
    throw InputError("'" + pvd_path + "': step time " + formatNumber(time) + " is not after the previous step's time " +
                     formatNumber(*previous) + " (ParaView would merge the two steps)");
}

}  // namespace tessella::io::detail
