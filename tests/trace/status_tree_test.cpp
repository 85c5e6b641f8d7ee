// The status tree (Algorithm-4) against the CSG it stores, evaluated whole
// after every toggle: the root's status, whether it changed, and the visits
// of the climb, which stops at the first node whose status stays. Random
// trees of unions, intersections and differences, toggled in random orders
// between resets, exercise the first toggle after a reset, whose climb under
// unions is counted without being made and written only when the tree is
// read or toggled again.

#include "capsim/trace/status_tree.h"

#include "support/scene_builders.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

using namespace capsim;
using namespace capsim::testing;

namespace {

// A random CSG tree over primitives next, next + 1, ...; unions weigh most,
// as in scene files, so that many leaves hang under unions only.
CsgNode random_tree(std::mt19937& rng, int depth, int& next) {
  std::uniform_int_distribution<int> pick(0, 9);
  if (depth == 0 || pick(rng) < 3) return leaf(next++);
  const int kind = pick(rng);
  const CsgOp o = kind < 6 ? CsgOp::Union : kind < 8 ? CsgOp::Intersection : CsgOp::Difference;
  std::vector<CsgNode> kids;
  const int count = 1 + pick(rng) % 4;
  for (int k = 0; k < count; ++k) kids.push_back(random_tree(rng, depth - 1, next));
  return op(o, std::move(kids));
}

// Every operator node's status from the leaves' alone, children before
// parents (nodes() lists a parent before its children).
std::vector<bool> node_values(const StatusTree& t, const std::vector<bool>& inside) {
  const std::vector<StatusNode>& nodes = t.nodes();
  std::vector<unsigned> operands(nodes.size(), 0);
  for (std::uint32_t p = 0; p < inside.size(); ++p)
    if (t.present(p) && inside[p] && t.leaf(p).parent >= 0) operands[t.leaf(p).parent] |= t.leaf(p).parent_side;
  std::vector<bool> value(nodes.size(), false);
  for (std::size_t i = nodes.size(); i-- > 0;) {
    value[i] = (nodes[i].truth >> operands[i]) & 1u;
    if (value[i] && nodes[i].parent >= 0) operands[nodes[i].parent] |= nodes[i].parent_side;
  }
  return value;
}

bool root_value(const StatusTree& t, const std::vector<bool>& inside, std::uint32_t any_present) {
  if (t.nodes().empty()) return inside[any_present];  // one leaf is the whole tree
  return node_values(t, inside)[0];
}

TEST(StatusTree, EveryToggleMatchesTheWholeTreeEvaluated) {
  std::mt19937 rng(20261127);
  int first_climbs_under_unions = 0, toggles = 0;
  for (int trial = 0; trial < 400; ++trial) {
    int count = 0;
    const CsgNode root = op(CsgOp::Union, {random_tree(rng, 4, count)});
    // The shape is read from a copy never toggled, so that only toggle itself
    // writes what a first climb left.
    const StatusTree shape(root, static_cast<std::size_t>(count));
    StatusTree t = shape;
    if (t.empty()) continue;
    std::vector<std::uint32_t> present;
    for (std::uint32_t p = 0; p < static_cast<std::uint32_t>(count); ++p)
      if (t.present(p)) present.push_back(p);
    std::uniform_int_distribution<std::size_t> pick(0, present.size() - 1);
    for (int ray = 0; ray < 6; ++ray) {
      t.reset();
      std::vector<bool> inside(static_cast<std::size_t>(count), false);
      const int steps = 1 + static_cast<int>(pick(rng) % 7);
      for (int step = 0; step < steps; ++step) {
        const std::uint32_t p = present[pick(rng)];
        const std::vector<bool> before = node_values(shape, inside);
        const bool root_before = root_value(shape, inside, p);
        inside[p] = !inside[p];
        const std::vector<bool> after = node_values(shape, inside);
        const bool root_after = root_value(shape, inside, p);
        // The climb: the leaf, then each node up to the first that stays.
        std::uint64_t visits = 1;
        bool under_unions = true;
        for (std::int32_t at = shape.leaf(p).parent; at >= 0; at = shape.nodes()[at].parent) {
          ++visits;
          under_unions = under_unions && shape.nodes()[at].truth == 0b1110u;
          if (before[at] == after[at]) break;
        }
        if (step == 0 && under_unions) ++first_climbs_under_unions;
        OpCounts ops;
        ASSERT_EQ(t.toggle(p, ops), root_before != root_after) << "trial " << trial << " step " << step;
        ASSERT_EQ(ops.tree_visits, visits) << "trial " << trial << " step " << step;
        ASSERT_EQ(t.root_inside(), root_after) << "trial " << trial << " step " << step;
        ASSERT_EQ(t.leaf_inside(p), inside[p]);
        ++toggles;
      }
    }
  }
  // The shortcut was taken, and the toggles after it read what it left.
  EXPECT_GT(first_climbs_under_unions, 500);
  EXPECT_GT(toggles, 5000);
}

// A first climb under unions, then the toggles that undo it: the statuses it
// left are the ones the climb would have written.
TEST(StatusTree, ToggleAfterAFirstClimbUnderUnionsSeesItsStatuses) {
  const CsgNode root = op(CsgOp::Union, {leaf(0), leaf(1), leaf(2), leaf(3)});
  StatusTree t(root, 4);
  OpCounts ops;
  EXPECT_TRUE(t.toggle(2, ops));  // into C: the union is entered
  EXPECT_EQ(ops.tree_visits, 3u);  // C, its pair (C u D), the root
  EXPECT_FALSE(t.toggle(3, ops));  // into D as well: (C u D) stays inside
  EXPECT_EQ(ops.tree_visits, 5u);
  EXPECT_FALSE(t.toggle(2, ops));  // out of C, still in D
  EXPECT_TRUE(t.toggle(3, ops));   // out of D: out of the union
  EXPECT_FALSE(t.root_inside());
  t.reset();
  EXPECT_TRUE(t.toggle(0, ops));
  // Read after a first climb, the nodes hold its statuses.
  const std::vector<StatusNode>& nodes = t.nodes();
  ASSERT_EQ(nodes.size(), 3u);
  EXPECT_EQ(nodes[0].status, StatusNode::kLeft | StatusNode::kSelf);
  EXPECT_EQ(nodes[1].status, StatusNode::kLeft | StatusNode::kSelf);
}

}  // namespace
