// Algorithm-4 of the paper: the status tree, evaluated bottom-up.

#include "capsim/trace/status_tree.h"

#include <algorithm>
#include <memory>
#include <variant>

namespace capsim {

namespace {

// Each operator's truth table, bit (2 * left + right): union 1110, intersection
// 1000, difference (left and not right) 0100. A table lookup keeps the climb of
// Algorithm-4 free of unpredictable branches.
constexpr std::uint8_t kTruth[3] = {0b1110u, 0b1000u, 0b0100u};
// StatusSelf sits just above the two operand bits that index the table.
static_assert(StatusNode::kSelf == 4 && (StatusNode::kLeft | StatusNode::kRight) == 3);
static_assert(static_cast<int>(CsgOp::Union) == 0 && static_cast<int>(CsgOp::Intersection) == 1 &&
              static_cast<int>(CsgOp::Difference) == 2);

// The CSG tree after simplification: binary operators over primitives, with no
// empty set left anywhere (an empty result is a null pointer).
struct Binary {
  bool is_leaf = false;
  std::uint32_t primitive = 0;
  CsgOp op = CsgOp::Union;
  std::unique_ptr<Binary> left, right;
};
using BinaryPtr = std::unique_ptr<Binary>;

BinaryPtr make_op(CsgOp op, BinaryPtr a, BinaryPtr b) {
  auto n = std::make_unique<Binary>();
  n->op = op;
  n->left = std::move(a);
  n->right = std::move(b);
  return n;
}

// A balanced binary tree over [first, last) under an associative operator, so
// that a crossing climbs O(log n) nodes rather than O(n).
BinaryPtr balanced(CsgOp op, std::vector<BinaryPtr>& items, std::size_t first, std::size_t last) {
  if (last - first == 1) return std::move(items[first]);
  const std::size_t mid = first + (last - first) / 2;
  BinaryPtr a = balanced(op, items, first, mid);
  BinaryPtr b = balanced(op, items, mid, last);
  return make_op(op, std::move(a), std::move(b));
}

BinaryPtr simplify(const CsgNode& node) {
  if (node.is_leaf) {
    auto leaf = std::make_unique<Binary>();
    leaf->is_leaf = true;
    leaf->primitive = static_cast<std::uint32_t>(node.primitive);
    return leaf;
  }
  std::vector<BinaryPtr> kids;
  for (const CsgNode& c : node.children) kids.push_back(simplify(c));
  switch (node.op) {
    case CsgOp::Union: {
      std::erase_if(kids, [](const BinaryPtr& k) { return !k; });
      if (kids.empty()) return nullptr;
      return balanced(CsgOp::Union, kids, 0, kids.size());
    }
    case CsgOp::Intersection: {
      if (kids.empty()) return nullptr;
      for (const BinaryPtr& k : kids)
        if (!k) return nullptr;
      return balanced(CsgOp::Intersection, kids, 0, kids.size());
    }
    case CsgOp::Difference: {
      if (kids.empty() || !kids[0]) return nullptr;
      BinaryPtr first = std::move(kids[0]);
      std::vector<BinaryPtr> rest;
      for (std::size_t i = 1; i < kids.size(); ++i)
        if (kids[i]) rest.push_back(std::move(kids[i]));
      if (rest.empty()) return first;
      // A - B - C = A - (B u C).
      return make_op(CsgOp::Difference, std::move(first), balanced(CsgOp::Union, rest, 0, rest.size()));
    }
  }
  return nullptr;
}

}  // namespace

StatusTree::StatusTree(const CsgNode& root, std::size_t primitive_count)
    : leaves_(primitive_count), union_depth_(primitive_count, -1), leaf_inside_(primitive_count, 0),
      leaf_epoch_(primitive_count, 0) {
  const BinaryPtr tree = simplify(root);
  if (!tree) return;
  has_root_ = true;
  // Emit nodes top-down so a node's parent always precedes it.
  struct Item {
    const Binary* node;
    std::int32_t parent;
    std::uint8_t side;  // the parent's status this node sets
  };
  std::vector<Item> stack = {{tree.get(), -1, StatusNode::kLeft}};
  // Per node: the number of operator nodes from it to the root when all are
  // unions, else -1.
  std::vector<std::int32_t> node_union_depth;
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    if (it.node->is_leaf) {
      leaves_[it.node->primitive] = {it.parent, it.side, true};
      union_depth_[it.node->primitive] = it.parent < 0 ? 0 : node_union_depth[it.parent];
      continue;
    }
    const auto index = static_cast<std::int32_t>(nodes_.size());
    const std::int32_t above = it.parent < 0 ? 0 : node_union_depth[it.parent];
    node_union_depth.push_back(it.node->op == CsgOp::Union && above >= 0 ? above + 1 : -1);
    nodes_.push_back({it.parent, it.side, kTruth[static_cast<int>(it.node->op)], 0, 0});
    stack.push_back({it.node->right.get(), index, StatusNode::kRight});
    stack.push_back({it.node->left.get(), index, StatusNode::kLeft});
  }
}

bool StatusTree::toggle(std::uint32_t p, OpCounts& ops) {
  write_first_climb();
  if (fresh_) {
    fresh_ = false;
    if (const std::int32_t depth = union_depth_[p]; depth >= 0) {
      // Every status is false: the leaf turns inside, and so does each union
      // above it, up to the root.
      leaf_epoch_[p] = epoch_;
      leaf_inside_[p] = 1;
      unwritten_climb_ = static_cast<std::int32_t>(p);
      ops.tree_visits += 1 + static_cast<std::uint64_t>(depth);
      root_inside_ = true;
      return true;
    }
  }
  std::uint64_t visits = 1;  // the leaf
  if (leaf_epoch_[p] != epoch_) {
    leaf_epoch_[p] = epoch_;
    leaf_inside_[p] = 0;
  }
  unsigned value = (leaf_inside_[p] ^= 1);
  std::int32_t at = leaves_[p].parent;
  unsigned side = leaves_[p].parent_side;
  while (at >= 0) {
    ++visits;
    StatusNode& node = nodes_[at];
    // A node this ray has not reached yet has every status false.
    const unsigned status = node.epoch == epoch_ ? node.status : 0u;
    node.epoch = epoch_;
    const unsigned operands = (status & ~side & 3u) | (value ? side : 0u);
    const unsigned self = (node.truth >> operands) & 1u;
    node.status = static_cast<std::uint8_t>(operands | self << 2);
    if (self == status >> 2) {  // the early stop of Algorithm-4
      ops.tree_visits += visits;
      return false;
    }
    value = self;
    side = node.parent_side;
    at = node.parent;
  }
  ops.tree_visits += visits;
  root_inside_ = value != 0;
  return true;
}

void StatusTree::write_first_climb() const {
  if (unwritten_climb_ < 0) return;
  const StatusLeaf& leaf = leaves_[static_cast<std::size_t>(unwritten_climb_)];
  unwritten_climb_ = -1;
  unsigned side = leaf.parent_side;
  for (std::int32_t at = leaf.parent; at >= 0;) {
    // As toggle's climb leaves a union reached with both operands outside:
    // the side it came from inside, and itself.
    StatusNode& node = nodes_[at];
    node.epoch = epoch_;
    node.status = static_cast<std::uint8_t>(side | StatusNode::kSelf);
    side = node.parent_side;
    at = node.parent;
  }
}

void StatusTree::reset() {
  unwritten_climb_ = -1;
  fresh_ = true;
  if (++epoch_ == 0) {
    // After 2^32 resets the epochs wrap: clear them all once.
    for (StatusNode& n : nodes_) n.epoch = 0;
    std::fill(leaf_epoch_.begin(), leaf_epoch_.end(), 0);
    epoch_ = 1;
  }
  root_inside_ = false;
}

}  // namespace capsim
