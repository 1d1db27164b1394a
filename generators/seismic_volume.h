#pragma once
// A post-stack seismic cube in memory, as the synthetic generator makes it and the SEG-Y writer
// writes it. No OpenGL, no CGAL.
#include <cstddef>
#include <vector>

namespace cutaway::generators {

/// Inline x crossline x time samples; amplitude of (inline i, crossline x, sample t) at
/// `amplitudes[(i * crosslines + x) * samples + t]` (dimensionless reflection amplitude).
struct SeismicVolume {
    int inlines = 0;
    int crosslines = 0;
    int samples = 0;
    int first_inline = 1;           ///< inline number of index 0 (numbers rise by 1)
    int first_crossline = 1;        ///< crossline number of index 0 (numbers rise by 1)
    int sample_interval_us = 4000;  ///< time between samples, microseconds
    std::vector<float> amplitudes;

    std::size_t trace_count() const { return std::size_t(inlines) * std::size_t(crosslines); }
    std::size_t index(int inline_index, int crossline_index, int sample) const {
        return (std::size_t(inline_index) * std::size_t(crosslines) + std::size_t(crossline_index)) *
                   std::size_t(samples) + std::size_t(sample);
    }
};

}  // namespace cutaway::generators
