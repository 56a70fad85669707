#pragma once
// Offscreen rendering to PNG. VTK 9.1 on Debian renders through X11 only, so a display is needed:
// headless machines run the program under xvfb-run.
#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>

#include <string>

namespace sdog::vis {

struct ImageSize {
  int width = 1600, height = 800;
};

/// Empty when there is an X display to render with; otherwise why there is none ("no X display
/// (DISPLAY is not set)", or the failed connection), for commands whose pictures are optional.
std::string display_unavailable();

/// Throws OutputError (saying to use xvfb-run) when there is no X display to render with or no
/// connection to it; commands that render at the end of a long computation call it before the
/// work.
void require_display();

/// An offscreen render window of the given size; throws OutputError when there is no X display.
vtkSmartPointer<vtkRenderWindow> offscreen_window(const ImageSize& size);

/// Renders the window and writes it as PNG (RGBA with a transparent background when asked).
/// Throws OutputError naming the path on failure.
void save_png(vtkRenderWindow* window, const std::string& path, bool transparent = false);

/// Parses "1600x800"; throws UsageError.
ImageSize parse_image_size(const std::string& text);

}  // namespace sdog::vis
