#pragma once
// How responsive the 3D view is while the solver plays (sdog-studio --measure-fps): the camera is
// turned a degree and the view drawn again as fast as the window's event loop allows, as a
// mouse rotating the model would, while the solver thread iterates and the window takes its
// states. Frames are timed from one to the next, so the time the window spends on the solver's
// states (the scene updated with every state it is shown) counts against the frame rate.
#include <vector>

namespace sdog::studio {

class MainWindow;

struct FrameRate {
  double seconds = 0;    ///< measured
  int frames = 0;        ///< camera moves drawn
  double fps = 0;        ///< frames / seconds
  double median_ms = 0;  ///< between consecutive frames
  double p95_ms = 0, max_ms = 0;
  int states_shown = 0;  ///< solver states the view took in that time
  int iterations = 0;    ///< solver iterations reported in that time
};

/// Plays the open session for `seconds` while drawing camera moves; pauses it afterwards. The
/// window must have a pattern open.
FrameRate measure_frame_rate(MainWindow& window, double seconds);

}  // namespace sdog::studio
