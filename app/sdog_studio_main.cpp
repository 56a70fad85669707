// sdog-studio: the desktop application (Qt widgets around sdog::studio::MainWindow).
//   sdog-studio [PATTERN.svg --res 31x21 --mode M --overlay L,... --view V]
//   sdog-studio --frame DIR/frame_NNNN.vtu | --run DIR [--iteration N]   opens a state a run saved
//   sdog-studio --screenshot FILE.png [PATTERN ... --iters N]   renders the window, saves it, exits
//   sdog-studio --measure-fps SECONDS PATTERN ...   plays, turns the camera, prints the frame rate
// Exit codes as sdog's: 0 success, 1 bad input or output, 2 usage error.
#include <QVTKOpenGLNativeWidget.h>
#include <CLI/CLI.hpp>
#include <QApplication>
#include <QSurfaceFormat>
#include <QTimer>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <string>

#include "app/blas_kernels.h"
#include "app/saved_state.h"
#include "app/studio_options.h"
#include "app/versions.h"
#include "base/errors.h"
#include "ui/studio/frame_rate.h"
#include "ui/studio/main_window.h"
#include "ui/vis/layers.h"

namespace {

QString about_text() {
  QString text =
      "<h3>Scalable DOGs studio</h3><p>Crease patterns to discrete orthogonal geodesic nets, "
      "deformed by the solver modes and inspected on the fine and coarse meshes.</p><table>";
  const auto versions = sdog::cli::software_versions().get<std::map<std::string, std::string>>();
  for (const auto& [name, version] : versions)
    text += QString("<tr><td>%1</td><td>%2</td></tr>")
                .arg(QString::fromStdString(name), QString::fromStdString(version));
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
    window.set_view(sdog::parse_enum<sdog::vis::View>(a.view));
    if (!a.overlay.empty()) {
      const auto layers = sdog::vis::parse_layers(a.overlay);
      for (sdog::vis::Layer l : sdog::enum_values<sdog::vis::Layer>()) window.set_layer(l, false);
      for (sdog::vis::Layer l : layers) window.set_layer(l, true);
    }
  } catch (const sdog::UsageError& e) {
    std::cerr << "sdog-studio: " << e.what() << "\n";
    return false;
  }
  return true;
}

// --frame or --run: the saved state on the model of its run, in the run's mode (at the frame's
// iteration) unless --mode says otherwise. Returns the iteration it opens at, or nothing: after a
// message on stderr when the saved state cannot be read (`exit_code` 1 or 2: the program ends), or
// when the window reported why it cannot open it.
std::optional<int> open_saved_state(sdog::studio::MainWindow& window, const StudioArgs& a,
                                    const CLI::App& cli, int& exit_code) {
  sdog::cli::SavedStateRequest request;
  request.frame = a.frame;
  request.run = a.run;
  if (a.iteration >= 0) request.iteration = a.iteration;
  request.command_line.pattern = a.pattern;
  request.command_line.res = a.res;
  request.given = [&cli](const std::string& option) {
    return (option == "PATTERN" || option == "--res") && cli.count(option) > 0;
  };
  try {
    const sdog::cli::SavedState saved = sdog::cli::load_saved_state(request);
    auto model = std::make_shared<const sdog::DogModel>(sdog::cli::saved_state_model(saved));
    const sdog::Workspace state = sdog::cli::saved_workspace(
        saved, *model, cli.count("--mode") ? std::optional<std::string>(a.mode) : std::nullopt);
    const std::string source = saved.run ? saved.run->record : saved.frame;
    if (window.open_state(model, state, QString::fromStdString(source))) return state.iteration;
  } catch (const sdog::Error& e) {
    std::cerr << "sdog-studio: " << e.what() << "\n";
    exit_code = sdog::exit_code(e.kind());
  }
  return std::nullopt;
}

// --measure-fps: once the first state is shown (and the solver is at iteration `until`), plays and
// turns the camera for the given time, prints the frame rate and quits.
void measure_when_shown(sdog::studio::MainWindow& window, const StudioArgs& a, int until,
                        QApplication& qt, const int& exit_code) {
  auto measuring = std::make_shared<bool>(false);
  QObject::connect(
      &window, &sdog::studio::MainWindow::snapshot_shown, &window, [&, until, measuring] {
        if (*measuring || window.snapshot()->iteration < until) return;
        *measuring = true;
        QTimer::singleShot(0, &window, [&] {
          const sdog::studio::FrameRate r = sdog::studio::measure_frame_rate(window, a.measure_fps);
          const sdog::vis::ImageSize view{window.renderer()->GetSize()[0],
                                          window.renderer()->GetSize()[1]};
          const sdog::DogModel& model = *window.model();
          std::printf(
              "view frame rate while playing %s on %s at %s (%d fine vertices), view %dx%d "
              "pixels:\n",
              window.snapshot()->mode.c_str(), model.pattern.source.c_str(),
              model.fine_res.str().c_str(), model.fine.vertex_count(), view.width, view.height);
          std::printf(
              "  %d frames in %.1f s: %.1f fps; between frames median %.1f ms, p95 %.1f ms, max "
              "%.1f ms\n",
              r.frames, r.seconds, r.fps, r.median_ms, r.p95_ms, r.max_ms);
          std::printf("  solver: %d iterations, %d states shown\n", r.iterations, r.states_shown);
          std::fflush(stdout);
          qt.exit(exit_code);
        });
      });
}

// --screenshot: saves the window once the state of iteration `until` is shown, and quits.
void screenshot_when_shown(sdog::studio::MainWindow& window, const StudioArgs& a, int until,
                           QApplication& qt, const int& exit_code) {
  QObject::connect(&window, &sdog::studio::MainWindow::snapshot_shown, &window, [&, until] {
    if (window.snapshot()->iteration < until) return;
    QTimer::singleShot(300, &window, [&] {
      if (window.save_window_image(QString::fromStdString(a.screenshot), /*frame_sheet=*/true)) {
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
    } else if (std::string(argv[i]) == "--version") {
      std::cout << sdog::cli::version_line("sdog-studio") << "\n";
      return 0;
    }
  if (!has_display(argc, argv)) {
    std::cerr << "sdog-studio: no display to open windows on (DISPLAY is not set); run it in a "
                 "desktop session, or "
                 "headless as `xvfb-run -a sdog-studio ...`\n";
    return 1;
  }
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication qt(argc, argv);  // takes Qt's own options out of argv
  try {
    cli.parse(argc, argv);
    sdog::cli::check_studio_args(a);
  } catch (const CLI::Success& e) {  // --version
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
  int until = a.iterations;  // the iteration the batch modes wait for
  if (!a.frame.empty() || !a.run.empty()) {
    const std::optional<int> start = open_saved_state(window, a, cli, exit_code);
    if (!start && (exit_code || batch)) return exit_code ? exit_code : 1;
    until += start.value_or(0);
  } else if (!a.pattern.empty() &&
             !window.open_pattern(QString::fromStdString(a.pattern), QString::fromStdString(a.res),
                                  QString::fromStdString(a.mode))) {
    if (batch) return 1;
  }
  if (a.iterations > 0) window.step(a.iterations);
  if (a.measure_fps > 0) measure_when_shown(window, a, until, qt, exit_code);
  if (!a.screenshot.empty()) screenshot_when_shown(window, a, until, qt, exit_code);
  const int code = qt.exec();
  return exit_code ? exit_code : code;
}
