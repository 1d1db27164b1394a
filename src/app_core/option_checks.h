#pragma once
// Validators every numeric and output option of `cutaway` shares (CLI11 runs them while parsing,
// before any file is read): a value must be a finite number inside the option's real range, an
// output must be writable where it is named, and two outputs of one run must differ. A refusal
// reads "--option: expected ..., found ..." and exits with code 2.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "io/file_identity.h"

namespace cutaway::app {

/// `value` as printf's %g writes it (1e-09, 0.5, 2.5e+06): how messages show numbers.
std::string number_text(double value);

/// A finite number in [low, high] (`unit` appended to the range in the message, e.g. "pixels";
/// `name` names the value within a multi-value option, e.g. "EL").
CLI::Validator finite_in(double low, double high, const std::string& unit = "", const std::string& name = "");
/// A finite number in (low, high]: for quantities that must be strictly positive.
CLI::Validator finite_above(double low, double high, const std::string& unit = "", const std::string& name = "");
/// Any finite number (for options whose range the consumer checks).
CLI::Validator finite_number();
/// Checks AZ EL DIST of an orbit camera option: AZ in [-360, 360] degrees, EL in [-89, 89] degrees
/// (straight up or down has no defined image "up"), DIST in [0, max_distance].
void check_orbit_values(CLI::Option& option, double max_distance);
/// One of `names` ("expected one of a|b|c, found 'x'").
CLI::Validator one_of(const std::vector<std::string>& names);
/// Text that is valid UTF-8: input paths end up in JSON reports, which hold UTF-8 only.
CLI::Validator utf8_text();
/// A property keyword: non-empty UTF-8 text (an empty one would silently mean the default).
CLI::Validator property_name();
/// A path an output can be written to (checked before any work: see io::output_path_problem).
CLI::Validator writable_output();
/// A directory output files can be written into, made when missing (io::output_directory_problem).
CLI::Validator writable_output_directory();

/// Throws std::invalid_argument when an output names the same file as an input or another output,
/// however spelled (io::overwrite_problem compares file identities); empty paths are options not given.
void refuse_overwrites(const std::vector<io::NamedFile>& inputs, const std::vector<io::NamedFile>& outputs);

/// Every command's --memory-limit-gb unless given (GiB): one default, so that a command line moved
/// from one subcommand to another keeps its bound.
constexpr double default_memory_limit_gib = 16;
/// The largest --memory-limit-gb accepted (GiB): far above any machine this runs on, small enough
/// that the byte count cannot overflow.
constexpr double max_memory_limit_gib = 1 << 20;
/// GiB (2^30 bytes, as every `cutaway` command reads --memory-limit-gb) to bytes.
std::size_t gib_to_bytes(double gib);
/// Registers --memory-limit-gb on `command`, bound to `gib` (default_memory_limit_gib unless the
/// caller set another) and checked to be in (0, max].
void add_memory_limit_option(CLI::App& command, double& gib, const std::string& what);

/// "expected WHAT within the memory limit of L GiB (--memory-limit-gb), found N GiB needed".
std::string memory_limit_problem(std::size_t bytes_needed, std::size_t limit_bytes, const std::string& what);

}  // namespace cutaway::app
