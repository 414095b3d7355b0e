// The supernodal elimination tree of a CHOLMOD supernodal factor, cut for two threads: a top set
// closed towards the roots and disjoint subtrees packed into kParts parts of about equal work.
// Work on different parts is independent (a supernode's rows below its diagonal block are its
// ancestors: in its own subtree or in the top set), and the top set comes after both parts. Used
// by the triangular solves (linalg/supernodal_factor.h, work = entries of L) and by the numeric
// factorisation (linalg/supernodal_cholesky.h, work = flops).
//
// The cut: starting from the roots, the subtree of largest work is moved to the top set again and
// again (its children become subtrees), at most kMaxCuts times or until that subtree is a single
// supernode; of these cuts the one with the shortest critical path, top work + largest part
// (longest-processing-time packing), is kept. It depends only on the tree and the work, never on
// the number of threads. The parents: SupernodalStructure::parents (linalg/supernodal_structure.h).
#pragma once

#include <array>
#include <vector>

namespace vs {

struct TreeCut {
  static constexpr int kParts = 2;
  static constexpr int kMaxCuts = 256;
  std::array<std::vector<int>, kParts> part;  // supernodes of each part, ascending
  std::vector<int> top;                       // the top set, ascending
  std::vector<int> group;                     // per supernode: its part, or -1 (top set)
  double top_fraction = 0.0;                  // of the total work
  double largest_part_fraction = 0.0;
};

// The cut of the tree given by `parent` with `work` per supernode.
TreeCut cut_tree(const std::vector<int>& parent, const std::vector<double>& work);

}  // namespace vs
