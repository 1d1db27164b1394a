#pragma once
// Command-line options bound to fields of a generator's parameter struct: an option given on the
// command line overrides the preset's value, one left out keeps it.
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include <CLI/CLI.hpp>

#include "app_core/option_checks.h"

namespace cutaway::app {

template <typename Parameters>
using ParameterOverrides = std::vector<std::function<void(Parameters&)>>;

/// Registers `--name VALUE` on `command`, bound to `field`.
template <typename Parameters, typename T>
void add_parameter_option(CLI::App* command, ParameterOverrides<Parameters>& overrides, const std::string& name,
                          T Parameters::*field, const std::string& help) {
    auto value = std::make_shared<T>();
    // NaN and infinity never reach a generator (its own checks give each value's range).
    CLI::Option* option = command->add_option(name, *value, help)->check(finite_number());
    // An unsigned field would take -1 as its largest value (strtoull wraps): refused instead.
    if constexpr (std::is_unsigned_v<T>) option->check(finite_in(0, double(std::numeric_limits<T>::max())));
    overrides.push_back([option, value, field](Parameters& p) {
        if (option->count() > 0) p.*field = *value;
    });
}

/// Applies the options that were given.
template <typename Parameters>
void apply_overrides(Parameters& parameters, const ParameterOverrides<Parameters>& overrides) {
    for (const auto& apply : overrides) apply(parameters);
}

}  // namespace cutaway::app
