// Fixed-size dense types of the element level (Eigen): 3-vectors and rotations for kinematics,
// 6-component connector vectors and matrices for behaviours, 12-DOF element rows and blocks.
// The names avoid clinch::Vec3 (std::array) of the model.
#pragma once

#include <Eigen/Dense>

namespace clinch {

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector12 = Eigen::Matrix<double, 12, 1>;
using Matrix12 = Eigen::Matrix<double, 12, 12>;
using Matrix6x12 = Eigen::Matrix<double, 6, 12>;

}  // namespace clinch
