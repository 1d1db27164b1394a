#pragma once
// `--cut-volume SPEC` (cut_volume.h): `box:X0,Y0,Z0,X1,Y1,Z1`, `cylinder:X0,Y0,Z0,X1,Y1,Z1,R`,
// `well:NAME[,R]`, `mesh:FILE`. Numbers in the model's coordinates and units.
#include <string>
#include <string_view>

#include "volumes/cut_volume.h"

namespace cutaway::volumes {

/// The volume SPEC names, checked (check_volume). Throws std::invalid_argument with a one-line
/// message "--cut-volume 'SPEC': ..." naming the field and what was expected.
CutVolume parse_cut_volume_spec(std::string_view spec);

/// "box:X0,Y0,Z0,X1,Y1,Z1 | cylinder:X0,Y0,Z0,X1,Y1,Z1,R | well:NAME[,R] | mesh:FILE", for help and messages.
std::string cut_volume_spec_forms();

}  // namespace cutaway::volumes
