// The element table (mesh/element_topology.hpp, fe/element_traits.hpp): every type has one data row
// and one formula row that agree, and the readers' and writers' names come from it.
#include "assembly/element_traits.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "mesh/element_topology.hpp"

namespace bb {
namespace element_traits_test {
namespace {

TEST(ElementTable, EveryTypeOnceInEnumeratorOrderWithAgreeingRows) {
  std::set<std::string_view> names;
  int i = 0;
  for (ElementType t : element_types()) {
    EXPECT_EQ(static_cast<int>(t), i++);
    const ElementTopology& data = topology(t);
    EXPECT_TRUE(names.insert(data.name).second) << data.name;
    EXPECT_EQ(element_type_named(data.name), t);
    with_element(t, [&]<class E>(E) {
      EXPECT_EQ(E::type, t) << data.name;
      EXPECT_EQ(E::nodes, data.nodes) << data.name;
      EXPECT_EQ(E::dim, data.dimension) << data.name;
      EXPECT_EQ(static_cast<int>(E::extrapolation().rows()), E::nodes) << data.name;
      EXPECT_EQ(static_cast<int>(E::extrapolation().cols()), E::points) << data.name;
    });
    EXPECT_GT(data.gmsh_type, 0) << data.name;
    EXPECT_TRUE(data.gmsh_order.empty() || static_cast<int>(data.gmsh_order.size()) == data.nodes) << data.name;
    EXPECT_GT(data.row_nonzeros, 0.0) << data.name;
    EXPECT_FALSE(data.calculix.empty()) << data.name;  // every type is read from decks
  }
  EXPECT_EQ(element_type_named("hex27"), std::nullopt);
}

TEST(ElementTable, GmshNodeOrderIsAPermutationThatKeepsTheCorners) {
  for (ElementType t : element_types()) {
    const ElementTopology& data = topology(t);
    if (data.gmsh_order.empty()) continue;
    std::set<int> seen(data.gmsh_order.begin(), data.gmsh_order.end());
    EXPECT_EQ(static_cast<int>(seen.size()), data.nodes) << data.name;
    EXPECT_EQ(*seen.begin(), 0);
    EXPECT_EQ(*seen.rbegin(), data.nodes - 1);
    for (int a = 0; a < data.corners; ++a) EXPECT_EQ(data.gmsh_order[static_cast<size_t>(a)], a) << data.name;
  }
}

}  // namespace
}  // namespace element_traits_test
}  // namespace bb
