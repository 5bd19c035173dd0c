#pragma once
/// \file The line a progress bar shows: what `glint render` draws on its terminal and what
/// the Python module's `render(..., progress=True)` writes to sys.stderr.

#include <string>

namespace glint {

/// "[#######.................................]  17.5%  elapsed 1.2 s  ETA 5.7 s" for
/// `fraction` (0 to 1) done after `elapsed_seconds`; the ETA assumes the rest goes as fast.
[[nodiscard]] std::string progress_text(double fraction, double elapsed_seconds);

}  // namespace glint
