// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "vtk_error_capture.hpp"

#include <mutex>

#include <vtkLogger.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

namespace tessella::io::detail {

namespace {

// VTK's output window, replaced: error texts go to the calling thread's
// active capture, nothing is printed.
class CapturingOutputWindow final : public vtkOutputWindow {
 public:
  static CapturingOutputWindow* New();
  vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow)

  void DisplayErrorText(const char* text) override {
    if (VtkErrorCapture* capture = VtkErrorCapture::active(); capture && text) capture->add(text);
  }
  void DisplayText(const char*) override {}
  void DisplayWarningText(const char*) override {}
  void DisplayGenericWarningText(const char*) override {}
  void DisplayDebugText(const char*) override {}

 protected:
  CapturingOutputWindow() = default;
};

vtkStandardNewMacro(CapturingOutputWindow);

}  // namespace

void silenceVtkOutput() {
  static std::once_flag once;
  std::call_once(once, [] {
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    vtkOutputWindow::SetInstance(vtkSmartPointer<CapturingOutputWindow>::New());
  });
}

}  // namespace tessella::io::detail
