#include "rccm/contact/delassus.hpp"

namespace rccm {

void DenseDelassus::multiply(const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> u) const {
  u.noalias() = W_ * y;
}

void DenseDelassus::add_response(Eigen::Index first, const LocalVector& dy, Eigen::VectorXd& u) const {
  u.noalias() += W_.middleCols(first, dy.size()) * dy;
}

}  // namespace rccm
