// The DOF numbering's two directions: the free part of a global vector, and a global vector built
// from free values with the constrained entries prescribed or zero.
#include <gtest/gtest.h>

#include "assembly/dof_map.hpp"

namespace bb {
namespace {

// Three nodes in 2D, node 0 held in x at 0.5 and node 2 held in y at -1.
Model three_nodes() {
  Model model;
  model.mesh.dim = 2;
  model.mesh.coords = Eigen::MatrixXd::Zero(3, 2);
  model.mesh.node_ids = {1, 2, 3};
  model.node_sets["a"] = {0};
  model.node_sets["b"] = {2};
  model.constraints.push_back({"a", {0}, 0.5});
  model.constraints.push_back({"b", {1}, -1.0});
  return model;
}

TEST(DofMap, FreePartAndGlobalVectorAreInverseOnTheFreeEquations) {
  const DofMap dofs = number_dofs(three_nodes());
  ASSERT_EQ(dofs.n_free, 4);
  ASSERT_EQ(dofs.n_global(), 6);
  const Eigen::VectorXd free = Eigen::VectorXd::LinSpaced(4, 1.0, 4.0);
  const Eigen::VectorXd with = to_global(dofs, free, true);
  const Eigen::VectorXd without = to_global(dofs, free, false);
  EXPECT_EQ(free_part(dofs, with), free);
  EXPECT_EQ(free_part(dofs, without), free);
  EXPECT_EQ(with[0], 0.5);   // node 0 x
  EXPECT_EQ(with[5], -1.0);  // node 2 y
  EXPECT_EQ(without[0], 0.0);
  EXPECT_EQ(without[5], 0.0);
  EXPECT_EQ(with.sum(), free.sum() - 0.5);
}

}  // namespace
}  // namespace bb
