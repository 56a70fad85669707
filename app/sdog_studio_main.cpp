// sdog-studio: the desktop application (Qt widgets around sdog::studio::MainWindow).
//   sdog-studio [PATTERN.svg --res 31x21 --mode M --overlay L,... --view V]
//   sdog-studio --screenshot FILE.png [PATTERN ... --iters N]   renders the window, saves it, exits
// Exit codes as sdog's: 0 success, 1 bad input or output, 2 usage error.
#include <CLI/CLI.hpp>
#include <QApplication>
#include <QSurfaceFormat>
#include <QTimer>
#include <QVTKOpenGLNativeWidget.h>
#include <iostream>
#include <map>

#include "app/versions.h"
#include "geometry/errors.h"
#include "solver/mode_factory.h"
#include "ui/studio/main_window.h"
#include "ui/vis/layers.h"

namespace {

struct StudioArgs {
  std::string pattern, res = "21x21", mode = "standard", overlay, view = "3d", screenshot, size = "1600x1000";
  int iterations = 0;
};

QString about_text() {
  QString text = "<h3>Scalable DOGs studio</h3><p>Crease patterns to discrete orthogonal geodesic nets, "
                 "deformed by the solver modes and inspected on the fine and coarse meshes.</p><table>";
  const auto versions = sdog::cli::software_versions().get<std::map<std::string, std::string>>();
  for (const auto& [name, version] : versions)
    text += QString("<tr><td>%1</td><td>%2</td></tr>").arg(QString::fromStdString(name), QString::fromStdString(version));
  return text + QString("<tr><td>qt</td><td>%1</td></tr></table>").arg(qVersion());
}

}  // namespace

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication qt(argc, argv);  // takes Qt's own options out of argv

  StudioArgs a;
  CLI::App cli{"Scalable DOGs studio: see and steer the solver"};
  cli.add_option("PATTERN", a.pattern, "crease pattern (SVG) to open");
  cli.add_option("--res", a.res, "grid lines XxY (odd values also build the coarse mesh)")->capture_default_str();
  cli.add_option("--mode", a.mode, "solver mode (" + sdog::known_modes() + ")")->capture_default_str();
  cli.add_option("--overlay", a.overlay, "comma-separated overlays to show instead of vertex-types,wireframe (" +
                                             sdog::vis::known_layers() + ")");
  cli.add_option("--view", a.view, "3d, flat or side-by-side")->capture_default_str();
  cli.add_option("--iters", a.iterations, "step the solver N iterations first")->check(CLI::Range(0, 100000));
  cli.add_option("--screenshot", a.screenshot, "save the window as PNG and exit (needs PATTERN)");
  cli.add_option("--size", a.size, "window size WIDTHxHEIGHT")->capture_default_str();
  try {
    cli.parse(argc, argv);
    if (!a.screenshot.empty() && a.pattern.empty()) throw CLI::ValidationError("--screenshot", "needs PATTERN");
  } catch (const CLI::ParseError& e) {
    return cli.exit(e);
  }

  sdog::studio::MainWindow window(about_text());
  const bool batch = !a.screenshot.empty();
  int exit_code = 0;
  if (batch)
    window.set_error_sink([&](const QString& message) {
      std::cerr << "sdog-studio: " << message.toStdString() << "\n";
      exit_code = 1;
      qt.exit(1);
    });
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
    return 2;
  }
  window.show();
  if (!a.pattern.empty() &&
      !window.open_pattern(QString::fromStdString(a.pattern), QString::fromStdString(a.res), QString::fromStdString(a.mode)))
    if (batch) return 1;
  if (a.iterations > 0) window.step(a.iterations);
  if (batch) {
    // Saves the window once the state of the last iteration asked for is shown.
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
  const int code = qt.exec();
  return exit_code ? exit_code : code;
}
