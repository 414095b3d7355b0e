#include "linalg/tree_cut.h"

#include <algorithm>

namespace vs {

TreeCut cut_tree(const std::vector<int>& parent, const std::vector<double>& work) {
  constexpr int kParts = TreeCut::kParts;
  const int ns = static_cast<int>(parent.size());
  std::vector<double> subtree(work);
  std::vector<std::vector<int>> children(static_cast<size_t>(ns));
  std::vector<int> roots;
  double total = 0.0;
  for (int j = 0; j < ns; ++j) {  // children (smaller indices) have added their subtrees
    total += work[j];
    if (parent[j] >= 0) {
      subtree[parent[j]] += subtree[j];
      children[parent[j]].push_back(j);
    } else {
      roots.push_back(j);
    }
  }
  // Longest-processing-time packing of the subtrees: the largest part, and each subtree's part.
  auto pack = [&](std::vector<int> trees, std::vector<int>* part_of) {
    std::sort(trees.begin(), trees.end(), [&](int a, int b) {
      return subtree[a] != subtree[b] ? subtree[a] > subtree[b] : a < b;
    });
    std::array<double, kParts> load{};
    for (int t : trees) {
      const int p = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
      load[p] += subtree[t];
      if (part_of) (*part_of)[t] = p;
    }
    return *std::max_element(load.begin(), load.end());
  };
  auto cut = [&](std::vector<int>* trees, double* top_work, std::vector<int>* top) {
    auto heaviest = std::max_element(trees->begin(), trees->end(), [&](int a, int b) {
      return subtree[a] != subtree[b] ? subtree[a] < subtree[b] : a > b;
    });
    if (heaviest == trees->end() || children[*heaviest].empty()) return false;
    const int j = *heaviest;
    trees->erase(heaviest);
    trees->insert(trees->end(), children[j].begin(), children[j].end());
    *top_work += work[j];
    if (top) top->push_back(j);
    return true;
  };
  // Cut the heaviest subtree while that helps; replay the best number of cuts.
  std::vector<int> trees = roots;
  double top_work = 0.0;
  double best = pack(trees, nullptr);
  int best_cuts = 0;
  for (int k = 1; k <= TreeCut::kMaxCuts && cut(&trees, &top_work, nullptr); ++k) {
    const double critical = top_work + pack(trees, nullptr);
    if (critical < best) best = critical, best_cuts = k;
  }
  TreeCut c;
  trees = roots;
  top_work = 0.0;
  for (int k = 0; k < best_cuts; ++k) cut(&trees, &top_work, &c.top);
  std::vector<int> part_of(static_cast<size_t>(ns), -1);
  const double largest = pack(trees, &part_of);
  c.group.assign(static_cast<size_t>(ns), -1);
  for (int t : trees) {  // every supernode of the subtree under t
    std::vector<int> stack{t};
    while (!stack.empty()) {
      const int j = stack.back();
      stack.pop_back();
      c.part[part_of[t]].push_back(j);
      c.group[j] = part_of[t];
      stack.insert(stack.end(), children[j].begin(), children[j].end());
    }
  }
  for (auto& p : c.part) std::sort(p.begin(), p.end());
  std::sort(c.top.begin(), c.top.end());
  c.top_fraction = total > 0.0 ? top_work / total : 0.0;
  c.largest_part_fraction = total > 0.0 ? largest / total : 0.0;
  return c;
}

}  // namespace vs
