#pragma once
// The process's heap policy. llvmpipe allocates its bins and vertex buffers anew for every batch of
// draws and frees them after rasterising it; glibc returns freed memory at the top of the heap to
// the system once it exceeds M_TRIM_THRESHOLD (128 KiB by default, adjusted as large blocks come
// and go), so the next batch faults those pages in again, zero-filled by the kernel: many minor
// page faults in every frame (sapphire, 1080p). Keeping freed memory for reuse removed nearly all
// of them and made the frame faster, most of the gain in the outer-face and stage-2 draws
// (alternating runs; commit 8eada0d has the numbers).
// The peak resident memory is unchanged (scale-10m, bytes per active cell).
#include <climits>
#include <cstddef>
#include <nlohmann/json.hpp>

namespace cutaway::app {

/// The free memory at the top of the heap glibc keeps instead of returning it (bytes): all of it.
inline constexpr std::size_t kept_free_heap_bytes = INT_MAX;

/// Call first in main(): sets M_TRIM_THRESHOLD to kept_free_heap_bytes. Returns whether the
/// allocator took it (a sanitizer's allocator may not).
bool keep_freed_heap_memory();

/// What stats.json records: kept_free_heap_bytes, or null where the allocator does not take the
/// policy (it is set again, which changes nothing where main() already set it).
nlohmann::json heap_trim_threshold_json();

}  // namespace cutaway::app
