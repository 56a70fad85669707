#include "ui/studio/frame_rate.h"

#include <vtkCamera.h>
#include <QEventLoop>
#include <QTimer>

#include <algorithm>
#include <chrono>

#include "ui/studio/main_window.h"

namespace sdog::studio {

FrameRate measure_frame_rate(MainWindow& window, double seconds) {
  using Clock = std::chrono::steady_clock;
  const auto ms = [](Clock::duration d) {
    return std::chrono::duration<double, std::milli>(d).count();
  };
  FrameRate r;
  const int reports_before = window.reports_received();
  int states = 0;
  const QMetaObject::Connection counting =
      QObject::connect(&window, &MainWindow::snapshot_shown, [&states] { ++states; });
  window.play();

  std::vector<double> gaps;
  QEventLoop loop;
  QTimer frames;
  frames.setInterval(0);  // a frame whenever the event loop is free
  const auto start = Clock::now();
  auto last = start;
  QObject::connect(&frames, &QTimer::timeout, [&] {
    window.renderer()->GetActiveCamera()->Azimuth(1.0);
    window.render();
    const auto now = Clock::now();
    gaps.push_back(ms(now - last));
    last = now;
    if (ms(now - start) >= 1000 * seconds) loop.quit();
  });
  frames.start();
  loop.exec();
  frames.stop();
  window.pause();
  QObject::disconnect(counting);

  r.seconds = ms(last - start) / 1000;
  r.frames = static_cast<int>(gaps.size());
  r.fps = r.seconds > 0 ? r.frames / r.seconds : 0;
  if (!gaps.empty()) {
    std::sort(gaps.begin(), gaps.end());
    r.median_ms = gaps[gaps.size() / 2];
    r.p95_ms = gaps[std::min(gaps.size() - 1, gaps.size() * 95 / 100)];
    r.max_ms = gaps.back();
  }
  r.states_shown = states;
  r.iterations = window.reports_received() - reports_before;
  return r;
}

}  // namespace sdog::studio
