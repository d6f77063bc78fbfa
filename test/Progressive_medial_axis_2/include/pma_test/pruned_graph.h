// The shape of a pruned medial axis as a graph (test-only code): its nodes
// are the kept vertices and the cut ends of curves, its edges the kept
// curves.  Counts its ends (nodes of degree 1), components and independent
// cycles; longest_path() is a reference for the centerline.

#ifndef PMA_TEST_PRUNED_GRAPH_H
#define PMA_TEST_PRUNED_GRAPH_H

#include <CGAL/Progressive_medial_axis_2/Medial_axis_significance_2.h>

#include <cstddef>
#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace pma_test {

struct Pruned_graph {
  int ends = 0, components = 0, cycles = 0;
};

// The nodes at the ends of each kept curve, numbered from 0: a kept vertex
// is one node (by its id number), every cut end a node of its own.
template <class K>
std::vector<std::pair<int, int> > pruned_ends(const CGAL::Pruned_medial_axis_2<K>& p, int& nodes)
{
  std::map<std::size_t, int> vertex_node;
  nodes = 0;
  auto node = [&](const typename CGAL::Medial_axis_2<K>::Vertex_handle& v) {
    const auto it = vertex_node.emplace(v.id_number(), nodes);
    if(it.second) ++nodes;
    return it.first->second;
  };
  std::vector<std::pair<int, int> > ends;
  for(const auto& c : p.curves()) {
    const int a = c.cut_at_begin() ? nodes++ : node(c.halfedge.source());
    const int b = c.cut_at_end() ? nodes++ : node(c.halfedge.target());
    ends.emplace_back(a, b);
  }
  return ends;
}

template <class K>
Pruned_graph pruned_graph(const CGAL::Pruned_medial_axis_2<K>& p)
{
  int n = 0;
  const std::vector<std::pair<int, int> > ends = pruned_ends(p, n);
  std::vector<int> parent(static_cast<std::size_t>(n)), degree(static_cast<std::size_t>(n), 0);
  for(int v = 0; v < n; ++v) parent[v] = v;
  std::function<int(int)> find = [&](int x) { return parent[x] == x ? x : parent[x] = find(parent[x]); };
  for(const auto& e : ends) {
    ++degree[e.first];
    ++degree[e.second];
    parent[find(e.first)] = find(e.second);
  }
  Pruned_graph g;
  for(int v = 0; v < n; ++v) {
    if(find(v) == v) ++g.components;
    if(degree[v] == 1) ++g.ends;
  }
  g.cycles = int(ends.size()) - n + g.components;
  return g;
}

// The longest path between two ends of a pruned axis without cycles, by a
// search from every end (quadratic: for small test shapes).
template <class K>
double longest_path(const CGAL::Pruned_medial_axis_2<K>& p)
{
  int n = 0;
  const std::vector<std::pair<int, int> > ends = pruned_ends(p, n);
  std::vector<std::vector<std::pair<int, double> > > adjacent(static_cast<std::size_t>(n));
  for(std::size_t i = 0; i < ends.size(); ++i) {
    const double length = p.curves()[i].length();
    adjacent[ends[i].first].emplace_back(ends[i].second, length);
    adjacent[ends[i].second].emplace_back(ends[i].first, length);
  }
  double longest = 0;
  for(int e = 0; e < n; ++e) {
    if(adjacent[e].size() != 1) continue;
    std::vector<double> dist(std::size_t(n), -1);
    std::vector<int> stack(1, e);
    dist[e] = 0;
    while(!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for(const auto& x : adjacent[v])
        if(dist[x.first] < 0) {
          dist[x.first] = dist[v] + x.second;
          stack.push_back(x.first);
        }
    }
    for(int v = 0; v < n; ++v)
      if(adjacent[v].size() == 1 && dist[v] > longest) longest = dist[v];
  }
  return longest;
}

} // namespace pma_test

#endif // PMA_TEST_PRUNED_GRAPH_H
