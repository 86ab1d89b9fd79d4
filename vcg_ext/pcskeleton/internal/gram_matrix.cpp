#include "pcskeleton/internal/gram_matrix.h"

#include "pcskeleton/core/errors.h"

#include <algorithm>
#include <string>

namespace pcskeleton {

GramMatrix::GramMatrix(const Factor& l) {
    const int n = int(l.cols());
    // L by columns: (LᵀL)(i, j) = Σ_k L(k, i) L(k, j) runs over the rows k that hold column j.
    columnStart_.assign(n + 1, 0);
    for (int k = 0; k < l.outerSize(); ++k)
        for (Factor::InnerIterator it(l, k); it; ++it) ++columnStart_[it.col() + 1];
    for (int j = 0; j < n; ++j) columnStart_[j + 1] += columnStart_[j];
    columnRow_.resize(columnStart_[n]);
    columnSlot_.resize(columnStart_[n]);
    std::vector<int> next(columnStart_.begin(), columnStart_.end() - 1);
    for (int k = 0; k < l.outerSize(); ++k) {
        for (Factor::InnerIterator it(l, k); it; ++it) {
            const int at = next[it.col()]++;
            columnRow_[at] = k;
            columnSlot_[at] = int(&it.value() - l.valuePtr());
        }
    }

    // Column j of the lower triangle: every i >= j sharing a row of L with j.
    std::vector<int> outer(n + 1, 0), inner, seen(n, -1);
    std::vector<int> column;
    for (int j = 0; j < n; ++j) {
        column.clear();
        for (int c = columnStart_[j]; c < columnStart_[j + 1]; ++c) {
            const int k = columnRow_[c];
            for (Factor::InnerIterator it(l, k); it; ++it) {
                const int i = int(it.col());
                if (i >= j && seen[i] != j) {
                    seen[i] = j;
                    column.push_back(i);
                }
            }
        }
        std::sort(column.begin(), column.end());
        inner.insert(inner.end(), column.begin(), column.end());
        outer[j + 1] = int(inner.size());
    }
    matrix_.resize(n, n);
    matrix_.resizeNonZeros(Eigen::Index(inner.size()));
    std::copy(outer.begin(), outer.end(), matrix_.outerIndexPtr());
    std::copy(inner.begin(), inner.end(), matrix_.innerIndexPtr());
    std::fill(matrix_.valuePtr(), matrix_.valuePtr() + inner.size(), 0.0);
    // Row j of L holds L(j, j), so (j, j) is in the pattern, first in its column.
    diagonalSlot_.resize(n);
    for (int j = 0; j < n; ++j) {
        if (outer[j] == outer[j + 1] || inner[outer[j]] != j)
            throw CallerError("GramMatrix: L(" + std::to_string(j) + ", " + std::to_string(j) + ") is not in L's pattern.");
        diagonalSlot_[j] = outer[j];
    }
}

void GramMatrix::update(const Factor& l, double scale) {
    const int n = int(matrix_.cols());
    const double* lValues = l.valuePtr();
    const int* outer = matrix_.outerIndexPtr();
    const int* inner = matrix_.innerIndexPtr();
    double* values = matrix_.valuePtr();
#pragma omp parallel
    {
        // Where row i of column j sits in `values`, for the column being computed.
        std::vector<int> slotOfRow(n, -1);
#pragma omp for schedule(dynamic, 256)
        for (int j = 0; j < n; ++j) {
            for (int s = outer[j]; s < outer[j + 1]; ++s) {
                slotOfRow[inner[s]] = s;
                values[s] = 0.0;
            }
            for (int c = columnStart_[j]; c < columnStart_[j + 1]; ++c) {
                const int k = columnRow_[c];
                const double lkj = lValues[columnSlot_[c]];
                for (Factor::InnerIterator it(l, k); it; ++it)
                    if (it.col() >= j) values[slotOfRow[it.col()]] += lkj * it.value();
            }
            for (int s = outer[j]; s < outer[j + 1]; ++s) values[s] *= scale;
        }
    }
}

}  // namespace pcskeleton
