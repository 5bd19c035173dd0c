#include "frame_sequence.h"

#include "mpi_session.h"

#include "glint/integrators/checkpoint.h"

#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace glint::app {

namespace {

constexpr int64_t kMaxFrame = 9'999'999;

int64_t frame_number(std::string_view text, std::string_view whole) {
    int64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < 0 || value > kMaxFrame)
        throw std::invalid_argument(fmt::format(
            "--frames: expected frame numbers from 0 to {} as FIRST-LAST, FIRST-LAST:STEP or N, comma-separated "
            "(1-120, 0-240:10, 1,5,10-20); got '{}'",
            kMaxFrame, whole));
    return value;
}

}  // namespace

std::vector<int64_t> parse_frames(std::string_view text) {
    std::vector<int64_t> frames;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const std::string_view item = text.substr(start, comma - start);
        // A step after ':' (Open Job Description's range expressions) or 'x' (Deadline's).
        const std::size_t dash = item.find('-'), x = item.find_first_of(":x");
        int64_t first = 0, last = 0, step = 1;
        if (dash == std::string_view::npos) {
            first = last = frame_number(item, text);
        } else {
            first = frame_number(item.substr(0, dash), text);
            last = frame_number(item.substr(dash + 1, x == std::string_view::npos ? x : x - dash - 1), text);
            if (x != std::string_view::npos) step = frame_number(item.substr(x + 1), text);
            if (last < first || step == 0)
                throw std::invalid_argument(fmt::format(
                    "--frames: expected FIRST ≤ LAST and a step of 1 or more in '{}'; got '{}'", item, text));
        }
        for (int64_t f = first; f <= last; f += step)
            if (std::find(frames.begin(), frames.end(), f) == frames.end()) frames.push_back(f);
        start = comma + 1;
    }
    return frames;
}

std::string frame_path(std::string_view pattern, int64_t frame) {
    const std::string name = std::filesystem::path(pattern).filename().string();
    const std::size_t first = name.find('#');
    const std::size_t end = first == std::string::npos ? first : name.find_first_not_of('#', first);
    if (first == std::string::npos || (end != std::string::npos && name.find('#', end) != std::string::npos))
        throw std::invalid_argument(fmt::format(
            "-o {}: expected one run of # in the file name for the frame number (out_####.exr: out_0001.exr, ...)",
            pattern));
    const std::size_t width = (end == std::string::npos ? name.size() : end) - first;
    const std::size_t at = pattern.size() - name.size() + first;
    return fmt::format("{}{:0{}}{}", pattern.substr(0, at), frame, width, pattern.substr(at + width));
}

int render_frames(const RenderOptions& opt) {
    const std::vector<int64_t> frames = parse_frames(*opt.frames);
    if (!(opt.fps > 0.0 && std::isfinite(opt.fps)))
        throw std::invalid_argument(
            fmt::format("--fps: expected a positive number of frames per second; got {}", opt.fps));
    if (!(opt.motion_blur >= 0.0 && opt.motion_blur <= 1.0))
        throw std::invalid_argument(fmt::format(
            "--motion-blur: expected the fraction of a frame the shutter is open, 0 to 1; got {}", opt.motion_blur));
    if (opt.scene.time || opt.scene.shutter)
        throw std::invalid_argument(
            "--frames sets each frame's time (FRAME / fps); expected no --time or --shutter "
            "(--motion-blur opens the shutter over part of a frame)");
    if (opt.resume)
        throw std::invalid_argument("--frames resumes a frame that has a checkpoint by itself; expected no --resume");
    if (opt.mpi && opt.mpi->distributed())
        throw std::invalid_argument(
            "--frames under mpirun: MPI renders one frame across ranks; give a frame range "
            "to a farm's job array instead (docs/scale-out.md)");
    const std::string pattern = !opt.output.empty() ? opt.output
                                : opt.scene_path.empty()
                                    ? std::string("spheres_####.png")
                                    : std::filesystem::path(opt.scene_path).stem().string() + "_####.png";
    (void)frame_path(pattern, 0);  // the pattern is checked before anything renders
    uint32_t rendered = 0, skipped = 0;
    for (const int64_t frame : frames) {
        RenderOptions one = opt;
        one.frames.reset();
        one.output = frame_path(pattern, frame);
        // Scene time in seconds, as motion keys and glTF animations count it.
        const auto open = float(double(frame) / opt.fps);
        one.scene.frame_shutter = Shutter{open, float((double(frame) + opt.motion_blur) / opt.fps)};
        const bool has_checkpoint = std::filesystem::exists(checkpoint_path_for(one.output));
        if (!opt.overwrite && has_checkpoint) {
            one.resume = true;  // an interrupted frame goes on where it stopped
        } else if (!opt.overwrite && std::filesystem::exists(one.output)) {
            if (!opt.quiet)
                fmt::print("frame {}: {} is there; skipped (--overwrite renders it again)\n", frame, one.output);
            ++skipped;
            continue;
        }
        int status = 0;
        try {
            status = render_image(one);
        } catch (const std::exception& e) {
            throw std::runtime_error(fmt::format("frame {}: {}", frame, e.what()));
        }
        if (status != 0) return status;
        ++rendered;
    }
    if (!opt.quiet)
        fmt::print("{} frame{}: {} rendered, {} already there\n", frames.size(), frames.size() == 1 ? "" : "s",
                   rendered, skipped);
    return 0;
}

}  // namespace glint::app
