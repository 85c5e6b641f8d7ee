#pragma once
// The status tree (Algorithm-4): the CSG tree stored bottom-up, operators at the
// nodes, primitives at the leaves, each node holding
//   Operator | PointerToParent | StatusSelf | StatusLeft | StatusRight.
// A boundary crossing toggles its leaf and propagates toward the root, stopping at
// the first node whose StatusSelf does not change.

#include "capsim/scene/scene.h"
#include "capsim/trace/op_counts.h"

#include <cstdint>
#include <vector>

namespace capsim {

struct StatusNode {
  // StatusSelf, StatusLeft and StatusRight are bits of `status`; left and right
  // together, (status & 3), index the Operator's truth table.
  static constexpr std::uint8_t kRight = 1, kLeft = 2, kSelf = 4;

  std::int32_t parent = -1;          // PointerToParent; -1 at the root
  std::uint8_t parent_side = kLeft;  // the parent's status it sets: kLeft or kRight
  std::uint8_t truth = 0;            // Operator, as a truth table: bit (2 * left + right) is self
  std::uint8_t status = 0;
  std::uint32_t epoch = 0;  // status is valid only when equal to the tree's epoch
};

// Where a primitive's leaf hangs: its parent operator node and side. A primitive
// that is the whole tree has parent -1; one that no longer contributes (inside an
// empty-set branch that the build removed) is absent.
struct StatusLeaf {
  std::int32_t parent = -1;
  std::uint8_t parent_side = StatusNode::kLeft;
  bool present = false;
};

// The status tree as built from a scene's CSG tree: n-ary operators become
// balanced chains of binary nodes, empty sets are simplified away, and every node
// starts with all statuses false (every primitive outside; no operator is inside
// when both of its operands are outside).
class StatusTree {
 public:
  StatusTree() = default;
  StatusTree(const CsgNode& root, std::size_t primitive_count);

  // Toggles primitive p's leaf and propagates. Returns true if the root's status
  // changed. Counts one visit for the leaf and one for each operator node reached.
  //
  // The first toggle after a reset, of a leaf under unions only, turns every
  // node above it inside and reaches the root: its count and result are known
  // without the climb, and the nodes' statuses are written only if the tree is
  // read or toggled again before the next reset. (A ray's first crossing is
  // often its last: in a union of solids the first one entered is the hit.)
  bool toggle(std::uint32_t p, OpCounts& ops);

  bool root_inside() const { return root_inside_; }
  bool leaf_inside(std::uint32_t p) const { return leaf_epoch_[p] == epoch_ && leaf_inside_[p]; }
  bool present(std::uint32_t p) const { return leaves_[p].present; }
  const StatusLeaf& leaf(std::uint32_t p) const { return leaves_[p]; }
  bool empty() const { return !has_root_; }

  // Back to the all-outside state of a fresh tree. O(1): every node and leaf
  // carries the epoch its statuses belong to, and a stale one reads as outside.
  void reset();

  const std::vector<StatusNode>& nodes() const {
    write_first_climb();
    return nodes_;
  }

 private:
  // The statuses a first toggle's climb leaves, written now (see toggle).
  void write_first_climb() const;

  // Written lazily by write_first_climb, which a const reader may call.
  mutable std::vector<StatusNode> nodes_;
  mutable std::int32_t unwritten_climb_ = -1;  // the leaf whose first climb is not written yet
  std::vector<StatusLeaf> leaves_;
  // Per leaf: the number of operator nodes above it when every one is a
  // union, else -1.
  std::vector<std::int32_t> union_depth_;
  bool fresh_ = true;  // no toggle since the last reset
  std::vector<char> leaf_inside_;
  std::vector<std::uint32_t> leaf_epoch_;
  std::uint32_t epoch_ = 1;
  bool root_inside_ = false;
  bool has_root_ = false;
};

}  // namespace capsim
