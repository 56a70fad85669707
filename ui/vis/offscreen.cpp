#include "ui/vis/offscreen.h"

#include <vtkPNGWriter.h>
#include <vtkWindowToImageFilter.h>

#include <chrono>
#include <cstdlib>
#include <mutex>
#include <regex>
#include <thread>

#include "base/errors.h"
#include "ui/vis/vtk_meshes.h"

// Last: Xlib defines macros (Status, Success, None) that clash with other headers.
#include <X11/Xlib.h>

namespace sdog::vis {
namespace {

// One connection to the X server for the whole process, handed to every window. VTK would open
// its own and abort the process when that fails, which happens now and then when several
// programs connect to the same Xvfb at once; here a failed connection is retried and then
// reported as an error.
Display* x_display() {
  static std::mutex mutex;
  static Display* display = nullptr;
  const std::lock_guard<std::mutex> lock(mutex);
  for (int attempt = 0; !display && attempt < 10; ++attempt) {
    if (attempt > 0) std::this_thread::sleep_for(std::chrono::milliseconds(100 * attempt));
    display = XOpenDisplay(nullptr);
  }
  if (!display)
    throw OutputError(std::string("cannot connect to the X display ") + std::getenv("DISPLAY") +
                      " (is the X server or xvfb-run still running?)");
  return display;
}

bool display_variable_set() {
  const char* display = std::getenv("DISPLAY");
  return display && *display;
}

}  // namespace

std::string display_unavailable() {
  if (!display_variable_set()) return "no X display (DISPLAY is not set)";
  try {
    x_display();
  } catch (const OutputError& e) {
    return e.what();
  }
  return "";
}

void require_display() {
  if (!display_variable_set())
    throw OutputError(
        "rendering needs an X display (VTK 9.1 on Debian renders through X11); run the command "
        "under xvfb-run, e.g. `xvfb-run -a sdog render ...`");
  x_display();
}

vtkSmartPointer<vtkRenderWindow> offscreen_window(const ImageSize& size) {
  require_display();
  take_vtk_error();  // installs the capturing output window
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetDisplayId(x_display());
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);  // deterministic pixels for regression images
  window->SetSize(size.width, size.height);
  return window;
}

void save_png(vtkRenderWindow* window, const std::string& path, bool transparent) {
  window->SetAlphaBitPlanes(transparent ? 1 : 0);
  window->Render();
  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput(window);
  if (transparent)
    grab->SetInputBufferTypeToRGBA();
  else
    grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  auto writer = vtkSmartPointer<vtkPNGWriter>::New();
  writer->SetFileName(path.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != 0) {
    const std::string why = take_vtk_error();
    throw OutputError(path + ": cannot write the PNG file" + (why.empty() ? "" : " (" + why + ")"));
  }
}

ImageSize parse_image_size(const std::string& text) {
  static const std::regex form("([0-9]{1,5})x([0-9]{1,5})");
  std::smatch m;
  if (!std::regex_match(text, m, form))
    throw UsageError("bad image size \"" + text + "\": expected WIDTHxHEIGHT such as 1600x800");
  ImageSize s{std::stoi(m[1]), std::stoi(m[2])};
  if (s.width < 16 || s.height < 16 || s.width > 8192 || s.height > 8192)
    throw UsageError("image size " + text + " out of range: width and height between 16 and 8192");
  return s;
}

}  // namespace sdog::vis
