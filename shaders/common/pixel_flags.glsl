// Flags stages 2 and 3 keep per pixel (the scene id target's second channel, src/cutaway/frame_targets.h).
const uint flag_primary = 1u;
const uint flag_cut_fill = 2u;     // a cell's inside seen through the cut
const uint flag_border = 4u;       // border line where a face meets the cut
const uint flag_edge = 8u;         // cell edge line
const uint flag_shell_cut = 16u;   // border line on a shell face
