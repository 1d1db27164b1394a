#pragma once
// KHR_debug messages of the current context, printed to stderr (notifications filtered out).
namespace cutaway::gl {

void enable_debug_output();

}  // namespace cutaway::gl
