/// @file live/run.hpp
/// Runs a Lab live: its page served on 127.0.0.1, the simulation paced to the wall clock, until
/// Ctrl-C or a duration (docs/live.md).
#pragma once

#include <iosfwd>
#include <string>

#include "opspace/live/lab.hpp"
#include "opspace/live/push.hpp"
#include "opspace/live/session.hpp"

namespace opspace::live {

/// How a live run is served and paced.
struct LiveOptions {
  int port = 0;             ///< 0: a free port
  /// Simulated seconds of the current run (from the page's opening) before the program ends; 0:
  /// until Ctrl-C
  double duration = 0.0;
  std::string csv_path;     ///< the session's log (empty: none)
  /// Wait for a page to open the event stream before the run starts (the programs' --live);
  /// false: start at once, for a caller with no page (tests/live/test_watchdog.cpp).
  bool wait_for_page = true;
  Spring spring;            ///< the push's spring
  double frame_rate = 60.0; ///< frames per second sent to the page
  /// Lag (wall seconds) after which the pacing gives up catching up and resynchronises,
  /// instead of running a burst of steps.
  double max_lag = 0.1;
  /// Wall seconds a loop iteration (a controller's tick among them) may take before the program
  /// is stopped with a message naming the hang (scenarios/watchdog.hpp; scripts/run sets it from
  /// OPSPACE_WATCHDOG); 0: no watchdog. A controller caught in an endless loop never returns, so
  /// the run cannot be reset: the program ends, and the page says it stopped.
  double watchdog = 0.0;
};

/// The bundled page script: $OPSPACE_LIVE_VIEWER if set, else the one CMake built
/// (build/PRESET/web/opspace-live.js).
std::string viewer_path();

/// The page of `lab`, whose pushes are clamped to `max_force` (N): its description
/// (docs/live.md#protocol) and the viewer, inlined; a page that says what is missing when the
/// viewer was not built.
std::string page(Lab& lab, double max_force);

/// What a paced run measured, for the terminal's summary.
struct LiveReport {
  double wall_seconds = 0.0;  ///< from the page's opening (the first step) to the end
  long steps = 0;             ///< simulation steps taken
  long resyncs = 0;           ///< times the pacing fell more than max_lag behind
  long frames = 0;            ///< frames published
};

/// Serves `lab` live (see the file comment), printing "live: http://127.0.0.1:PORT/" on `out`
/// first, then that it waits for the page: the run stays at t = 0 until a page (or any client)
/// opens the event stream, GET /events, so that the student's run and the reference's ghost
/// start when the page does. Ctrl-C (SIGINT) or SIGTERM ends it cleanly, waiting or not. Throws
/// std::runtime_error when it cannot listen.
LiveReport serve(Lab& lab, const LiveOptions& options, std::ostream& out);

/// The session stepped without clock, server or input for `duration` simulated seconds, as an
/// offline run steps (a tick at every instant k dt, k = 0 .. duration / dt, a step after each
/// but the last): its log then equals the offline run's, column for column.
void run_unpaced(Session& session, double duration);

}  // namespace opspace::live
