#include "eclipse/step_clock.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace cutaway::eclipse {

std::string date_at(const std::vector<eclipse::ReportStep>& steps, double time_step) {
    if (steps.empty()) return {};
    const double clamped = std::clamp(time_step, 0.0, double(steps.size() - 1));
    const std::size_t lower = std::size_t(std::floor(clamped));
    const std::size_t upper = std::min(lower + 1, steps.size() - 1);
    const eclipse::ReportStep& from = steps[lower];
    const double days_between = steps[upper].elapsed_days - from.elapsed_days;
    using namespace std::chrono;
    const sys_days start = year_month_day{year{from.year}, month{unsigned(from.month)}, day{unsigned(from.day)}};
    const year_month_day shown{start + days{std::lround((clamped - double(lower)) * days_between)}};
    char text[16];
    std::snprintf(text, sizeof text, "%04d-%02u-%02u", int(shown.year()), unsigned(shown.month()), unsigned(shown.day()));
    return text;
}

std::string step_caption(const std::string& property, const std::string& date, double time_step, std::size_t step_count) {
    char step[64];
    std::snprintf(step, sizeof step, "(step %.4g of 0-%zu)", time_step, step_count > 0 ? step_count - 1 : 0);
    return property + "  " + (date.empty() ? "" : date + "  ") + step;
}

}  // namespace cutaway::eclipse
