#pragma once
// Collects the error and warning messages a VTK object emits, so that library
// code can turn them into exceptions instead of letting VTK print them.

#include <string>

#include <vtkAlgorithm.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkObject.h>

namespace tessella::io::detail {

class VtkErrorCapture final : public vtkCommand {
 public:
  static VtkErrorCapture* New() { return new VtkErrorCapture; }

  void Execute(vtkObject* /*caller*/, unsigned long event, void* call_data) override {
    // Warnings are swallowed too: an observer is what stops VTK from printing.
    if (event != vtkCommand::ErrorEvent) return;
    if (!errors_.empty()) errors_ += "; ";
    errors_ += call_data ? cleaned(static_cast<const char*>(call_data)) : std::string("unknown VTK error");
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
  // "ERROR: In file.cxx, line N\nvtkClass (0x1234): what" -> "what"
  static std::string cleaned(std::string s) {
    if (s.rfind("ERROR: In ", 0) == 0 || s.rfind("Warning: In ", 0) == 0) {
      const auto eol = s.find('\n');
      s = eol == std::string::npos ? std::string() : s.substr(eol + 1);
    }
    if (s.rfind("vtk", 0) == 0) {
      const auto colon = s.find("): ");
      if (colon != std::string::npos && colon < 120) s = s.substr(colon + 3);
    }
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s.empty() ? std::string("unknown VTK error") : s;
  }
  std::string errors_;
};

}  // namespace tessella::io::detail
