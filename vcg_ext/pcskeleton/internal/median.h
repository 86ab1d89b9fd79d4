// The median of some values: the middle one by nth_element (for an even count, the upper
// of the two middle ones). The outlier test, the surface noise measure, refinement's
// criteria and the reconstruction's typical radius all take it this way.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace pcskeleton {

// `values` must not be empty.
inline double median(std::vector<double> values) {
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

// The value that a `share` (0 to 1) of `values` do not exceed: the one at that place in
// their order, by nth_element. `values` must not be empty.
inline double quantile(std::vector<double> values, double share) {
    const auto place = values.begin() + std::ptrdiff_t(share * double(values.size() - 1));
    std::nth_element(values.begin(), place, values.end());
    return *place;
}

}  // namespace pcskeleton
