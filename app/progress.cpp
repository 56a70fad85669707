#include "app/progress.h"

#include <unistd.h>

#include <cstdio>

namespace sdog::cli {

ProgressBar::ProgressBar(int total, bool enabled)
    : total_(total),
      enabled_(enabled && isatty(fileno(stderr))),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
  finish();
}

void ProgressBar::on_iteration(const IterationReport& r, const Dofs&) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && r.iteration < total_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  drawn_ = true;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double eta = r.iteration > 0 ? elapsed / r.iteration * (total_ - r.iteration) : 0;
  constexpr int kWidth = 24;
  const int filled = total_ > 0 ? kWidth * r.iteration / total_ : kWidth;
  char bar[kWidth + 1];
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '.';
  bar[kWidth] = 0;
  std::fprintf(stderr, "\r[%s] %d/%d  t %.2f  objective %.5g  dog %.1e  %.0f ms/it  ETA %.0f s   ",
               bar, r.iteration, total_, r.t, r.diagnostics.objective, r.diagnostics.dog_max,
               1000 * elapsed / std::max(1, r.iteration), eta);
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (!drawn_) return;
  std::fprintf(stderr, "\r%100s\r", "");
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace sdog::cli
