#include "material/flow_direction.h"

#include <Eigen/LU>

namespace vs {

FlowDirectionBall::FlowDirectionBall(const Eigen::Matrix2d& A) : Ainv3_(3.0 * A.inverse()) {}

}  // namespace vs
