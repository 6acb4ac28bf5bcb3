// The sparse matrix type of rccm (column-major, double).
#pragma once

#include <Eigen/SparseCore>

namespace rccm {

using SparseMatrix = Eigen::SparseMatrix<double>;

}  // namespace rccm
