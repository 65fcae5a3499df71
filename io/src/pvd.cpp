// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/io/pvd.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include "tessella/io/text_file.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/excerpt.hpp"
#include "tessella/tissue/format.hpp"
#include "vtk_error_capture.hpp"

namespace tessella::io {

namespace {

std::string xmlEscaped(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char ch : s) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += ch;
    }
  }
  return out;
}

}  // namespace

void writePvdFile(const std::string& path, std::span<const PvdEntry> entries, bool durable) {
  for (const PvdEntry& e : entries)
    if (!std::isfinite(e.time))
      throw InputError("'" + path + "': time " + formatNumber(e.time) + " of '" + e.file + "' is not finite");
  std::string text =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const PvdEntry& e : entries)
    text += "    <DataSet timestep=\"" + formatNumber(e.time) + "\" group=\"\" part=\"0\" file=\"" +
            xmlEscaped(e.file) + "\"/>\n";
  text += "  </Collection>\n</VTKFile>\n";
  writeTextFile(path, text, durable);
}

std::vector<PvdEntry> readPvdFile(const std::string& path) {
  auto fail = [&](const std::string& problem) -> InputError { return InputError("'" + path + "': " + problem); };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw fail("no such file");
  vtkNew<vtkXMLDataParser> parser;
  vtkNew<detail::VtkErrorCapture> errors;
  errors->watch(parser);
  parser->SetFileName(path.c_str());
  if (!parser->Parse() || errors->failed())
    throw fail("not a well-formed XML file" + (errors->failed() ? " (" + errors->message() + ")" : std::string()));
  vtkXMLDataElement* root = parser->GetRootElement();
  if (!root || std::string(root->GetName()) != "VTKFile" || !root->GetAttribute("type") ||
      std::string(root->GetAttribute("type")) != "Collection")
    throw fail("not a ParaView collection (expected <VTKFile type=\"Collection\">)");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  if (!collection) throw fail("has no <Collection> element");
  std::vector<PvdEntry> entries;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* dataset = collection->GetNestedElement(i);
    if (std::string(dataset->GetName()) != "DataSet") continue;
    const char* timestep = dataset->GetAttribute("timestep");
    const char* file = dataset->GetAttribute("file");
    const std::string which = "DataSet " + std::to_string(entries.size());
    if (!file) throw fail(which + " has no file attribute");
    if (!timestep) throw fail(which + " ('" + excerpt(file) + "') has no timestep attribute");
    char* end = nullptr;
    errno = 0;
    const double time = std::strtod(timestep, &end);
    if (end == timestep || *end != '\0' || errno == ERANGE || !std::isfinite(time))
      throw fail(which + " ('" + excerpt(file) + "') has timestep '" + excerpt(timestep) + "', not a finite number");
    entries.push_back({time, file});  // the parser has already decoded XML entities
  }
  return entries;
}

}  // namespace tessella::io
