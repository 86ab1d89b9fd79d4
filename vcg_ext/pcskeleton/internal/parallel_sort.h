// std::sort on every core (libstdc++'s parallel mode, through OpenMP). Sorting the whole
// cloud's keys is a large share of a multi-million-point run. Elements that compare equal
// may come out in any order: sort keys that are distinct (a key and its index) for a result
// that is the same on any number of threads.
#pragma once

#include <algorithm>

#ifdef _OPENMP
#include <parallel/algorithm>
#endif

namespace pcskeleton {

template <class RandomIt>
void parallelSort(RandomIt begin, RandomIt end) {
#ifdef _OPENMP
    __gnu_parallel::sort(begin, end);
#else
    std::sort(begin, end);
#endif
}

}  // namespace pcskeleton
