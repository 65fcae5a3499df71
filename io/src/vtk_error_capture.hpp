// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Collects the error and warning messages a VTK object emits, so that library
// code can turn them into exceptions instead of letting VTK print them.
//
// Objects VTK creates inside a reader (an XML element, a data array) cannot be
// watched; their errors go to VTK's logger and output window, which print to
// stderr. The first capture therefore turns VTK's stderr logging off and
// replaces the output window with one that hands error texts to the capture
// alive on the calling thread (and drops everything else).

#include <string>
#include <vector>

#include <vtkAlgorithm.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkObject.h>

namespace tessella::io::detail {

/// Silences VTK's own printing (once per process); see above.
void silenceVtkOutput();

class VtkErrorCapture final : public vtkCommand {
 public:
  static VtkErrorCapture* New() { return new VtkErrorCapture; }

  void Execute(vtkObject* /*caller*/, unsigned long event, void* call_data) override {
    // Warnings are swallowed too: an observer is what stops VTK from printing.
    if (event != vtkCommand::ErrorEvent) return;
    add(call_data ? static_cast<const char*>(call_data) : "");
  }
  /// Records one error text (each distinct message once; the pipeline's
  /// "Algorithm vtkX failed" only when nothing says more).
  void add(const std::string& text) {
    const std::string message = cleaned(text);
    const bool generic = message.rfind("Algorithm ", 0) == 0 && message.find(" failed") != std::string::npos;
    for (const std::string& seen : messages_)
      if (seen == message) return;
    if (generic && !messages_.empty()) return;
    if (!generic && messages_.size() == 1 && generic_first_) {
      messages_.clear();
      errors_.clear();
    }
    generic_first_ = messages_.empty() && generic;
    messages_.push_back(message);
    if (!errors_.empty()) errors_ += "; ";
    errors_ += message;
  }
  /// The capture that receives the output window's errors on this thread.
  static VtkErrorCapture*& active() {
    static thread_local VtkErrorCapture* capture = nullptr;
    return capture;
  }
  bool failed() const { return !errors_.empty(); }
  const std::string& message() const { return errors_; }

  /// Observes errors and warnings of `object`.
  void watch(vtkObject* object) {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }
  /// Observes an algorithm and its pipeline executive, which reports a
  /// failed request on its own (and would print it).
  void watch(vtkAlgorithm* algorithm) {
    watch(static_cast<vtkObject*>(algorithm));
    watch(static_cast<vtkObject*>(algorithm->GetExecutive()));
  }

 private:
  VtkErrorCapture() {
    silenceVtkOutput();
    if (!active()) active() = this;
  }
  ~VtkErrorCapture() override {
    if (active() == this) active() = nullptr;
  }

  // "ERROR: In file.cxx, line N\nvtkClass (0x1234): what\n<dump>" -> "what":
  // the first line only (VTK appends object dumps, "vtkInformation (0x..)
  // Debug: Off ..."), without object addresses.
  static std::string cleaned(std::string s) {
    if (s.rfind("ERROR: In ", 0) == 0 || s.rfind("Warning: In ", 0) == 0) {
      const auto eol = s.find('\n');
      s = eol == std::string::npos ? std::string() : s.substr(eol + 1);
    }
    if (s.rfind("vtk", 0) == 0) {
      const auto colon = s.find("): ");
      if (colon != std::string::npos && colon < 120) s = s.substr(colon + 3);
    }
    if (const auto eol = s.find('\n'); eol != std::string::npos) s.erase(eol);
    // The pipeline's "Algorithm vtkX (0x..) returned failure for request: vtkInformation (0x..)".
    if (const auto request = s.find(" returned failure for request"); request != std::string::npos)
      s = s.substr(0, request) + " failed";
    for (auto open = s.find("(0x"); open != std::string::npos; open = s.find("(0x", open)) {
      const auto close = s.find(')', open);
      if (close == std::string::npos) break;
      if (open > 0 && s[open - 1] == ' ') --open;
      s.erase(open, close - open + 1);
    }
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '.')) s.pop_back();
    return s.empty() ? std::string("unknown VTK error") : s;
  }
  std::string errors_;
  std::vector<std::string> messages_;
  bool generic_first_ = false;
};

}  // namespace tessella::io::detail
