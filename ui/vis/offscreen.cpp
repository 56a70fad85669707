#include "ui/vis/offscreen.h"

#include <vtkPNGWriter.h>
#include <vtkWindowToImageFilter.h>

#include <cstdlib>
#include <regex>

#include "geometry/errors.h"
#include "ui/vis/vtk_meshes.h"

namespace sdog::vis {

vtkSmartPointer<vtkRenderWindow> offscreen_window(const ImageSize& size) {
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
    throw OutputError(
        "rendering needs an X display (VTK 9.1 on Debian renders through X11); run the command "
        "under xvfb-run, e.g. `xvfb-run -a sdog render ...`");
  take_vtk_error();  // installs the capturing output window
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
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
