#pragma once
// `glint render --frames`: an animation as one image per frame, for render farms (Slurm job
// arrays, Open Job Description, Deadline): frame f shows scene time f / fps, each frame is
// written atomically, and a frame already on disk is skipped, so a task that is killed and
// run again renders only what is missing (Blender's command-line frame ranges do the same).

#include "render_command.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace glint::app {

/// "1-120", "7", "0-240:10" or "0-240x10" (every 10th), "1,5,10-20" (Open Job Description's
/// integer range expressions, which a farm hands a task as its chunk of frames): the frames, in the order given, each
/// once. Throws std::invalid_argument for anything else, or a range that ends before it starts.
[[nodiscard]] std::vector<int64_t> parse_frames(std::string_view text);

/// `pattern` with its one run of '#' replaced by `frame`, zero-padded to the run's length
/// ("out_####.exr", 7 → "out_0007.exr"; longer numbers are not cut). Throws
/// std::invalid_argument unless the pattern's file name has exactly one run of '#'.
[[nodiscard]] std::string frame_path(std::string_view pattern, int64_t frame);

/// Render the frames `options.frames` names, each with `render_image`; returns 0 when every
/// frame is on disk, else the status of the frame that stopped the run (128 + a signal).
/// Throws for a mistake, naming the frame.
[[nodiscard]] int render_frames(const RenderOptions& options);

}  // namespace glint::app
