// sdog-studio: the desktop application (Qt widgets around sdog::studio::MainWindow).
//   sdog-studio [PATTERN.svg --res 31x21 --mode M --overlay L,... --view V]
//   sdog-studio --screenshot FILE.png [PATTERN ... --iters N]   renders the window, saves it, exits
//   sdog-studio --measure-fps SECONDS PATTERN ...   plays, turns the camera, prints the frame rate
// Exit codes as sdog's: 0 success, 1 bad input or output, 2 usage error.
#include <CLI/CLI.hpp>
#include <QApplication>
#include <QSurfaceFormat>
#include <QTimer>
#include <QVTKOpenGLNativeWidget.h>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <iostream>
#include <map>
#include <memory>

#include "app/blas_kernels.h"
#include "app/studio_options.h"
#include "app/versions.h"
#include "base/errors.h"
#include "ui/studio/frame_rate.h"
#include "ui/studio/main_window.h"
#include "ui/vis/layers.h"

namespace {

QString about_text() {
  QString text = "<h3>Scalable DOGs studio</h3><p>Crease patterns to discrete orthogonal geodesic nets, "
                 "deformed by the solver modes and inspected on the fine and coarse meshes.</p><table>";
  const auto versions = sdog::cli::software_versions().get<std::map<std::string, std::string>>();
  for (const auto& [name, version] : versions)
    text += QString("<tr><td>%1</td><td>%2</td></tr>").arg(QString::fromStdString(name), QString::fromStdString(version));
  return text + QString("<tr><td>qt</td><td>%1</td></tr></table>").arg(qVersion());
}

/// True when Qt has somewhere to show windows: an X or Wayland display, or a platform chosen
/// by QT_QPA_PLATFORM or -platform. Without one, QApplication aborts.
bool has_display(int argc, char** argv) {
  for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
    if (const char* value = std::getenv(name); value && *value) return true;
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "-platform") return true;
  return false;
}

using sdog::cli::StudioArgs;

// Window size, view and overlays from the command line; false (after a message) for bad values.
bool configure_window(sdog::studio::MainWindow& window, const StudioArgs& a) {
  try {
    const sdog::vis::ImageSize size = sdog::vis::parse_image_size(a.size);
    window.resize(size.width, size.height);
    window.set_view(sdog::vis::parse_view(a.view));
    if (!a.overlay.empty()) {
      const auto layers = sdog::vis::parse_layers(a.overlay);
      for (sdog::vis::Layer l : sdog::vis::all_layers()) window.set_layer(l, false);
      for (sdog::vis::Layer l : layers) window.set_layer(l, true);
    }
  } catch (const std::exception& e) {
    std::cerr << "sdog-studio: " << e.what() << "\n";
    return false;
  }
  return true;
}

// --measure-fps: once the first state is shown (and the iterations asked for are done), plays and
// turns the camera for the given time, prints the frame rate and quits.
void measure_when_shown(sdog::studio::MainWindow& window, const StudioArgs& a, QApplication& qt, const int& exit_code) {
  auto measuring = std::make_shared<bool>(false);
  QObject::connect(&window, &sdog::studio::MainWindow::snapshot_shown, &window, [&, measuring] {
    if (*measuring || window.snapshot()->iteration < a.iterations) return;
    *measuring = true;
    QTimer::singleShot(0, &window, [&] {
      const sdog::studio::FrameRate r = sdog::studio::measure_frame_rate(window, a.measure_fps);
      const sdog::vis::ImageSize view{window.renderer()->GetSize()[0], window.renderer()->GetSize()[1]};
      std::printf("view frame rate while playing %s on %s at %s (%d fine vertices), view %dx%d pixels:\n",
                  a.mode.c_str(), a.pattern.c_str(), a.res.c_str(), window.model()->fine.vertex_count(), view.width,
                  view.height);
      std::printf("  %d frames in %.1f s: %.1f fps; between frames median %.1f ms, p95 %.1f ms, max %.1f ms\n",
                  r.frames, r.seconds, r.fps, r.median_ms, r.p95_ms, r.max_ms);
      std::printf("  solver: %d iterations, %d states shown\n", r.iterations, r.states_shown);
      std::fflush(stdout);
      qt.exit(exit_code);
    });
  });
}

// --screenshot: saves the window once the state of the last iteration asked for is shown, and quits.
void screenshot_when_shown(sdog::studio::MainWindow& window, const StudioArgs& a, QApplication& qt,
                           const int& exit_code) {
  QObject::connect(&window, &sdog::studio::MainWindow::snapshot_shown, &window, [&] {
    if (window.snapshot()->iteration < a.iterations) return;
    QTimer::singleShot(300, &window, [&] {
      if (window.save_window_image(QString::fromStdString(a.screenshot))) {
        std::cout << "wrote " << a.screenshot << "\n";
        qt.exit(exit_code);
      }
    });
  });
}

}  // namespace

int main(int argc, char** argv) {
  sdog::use_avx2_blas_kernels(argv);
  StudioArgs a;
  CLI::App cli;
  sdog::cli::add_studio_options(cli, a);
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {  // no window needed
      std::cout << cli.help();
      return 0;
    }
  if (!has_display(argc, argv)) {
    std::cerr << "sdog-studio: no display to open windows on (DISPLAY is not set); run it in a desktop session, or "
                 "headless as `xvfb-run -a sdog-studio ...`\n";
    return 1;
  }
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication qt(argc, argv);  // takes Qt's own options out of argv
  try {
    cli.parse(argc, argv);
    sdog::cli::check_studio_args(a);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "sdog-studio: " << e.what() << " (run `sdog-studio --help` for usage)\n";
    return 2;
  }

  sdog::studio::MainWindow window(about_text());
  const bool batch = !a.screenshot.empty() || a.measure_fps > 0;
  int exit_code = 0;
  if (batch)
    window.set_error_sink([&](const QString& message) {
      std::cerr << "sdog-studio: " << message.toStdString() << "\n";
      exit_code = 1;
      qt.exit(1);
    });
  if (!configure_window(window, a)) return 2;
  window.show();
  if (!a.pattern.empty() &&
      !window.open_pattern(QString::fromStdString(a.pattern), QString::fromStdString(a.res), QString::fromStdString(a.mode)))
    if (batch) return 1;
  if (a.iterations > 0) window.step(a.iterations);
  if (a.measure_fps > 0) measure_when_shown(window, a, qt, exit_code);
  if (!a.screenshot.empty()) screenshot_when_shown(window, a, qt, exit_code);
  const int code = qt.exec();
  return exit_code ? exit_code : code;
}
