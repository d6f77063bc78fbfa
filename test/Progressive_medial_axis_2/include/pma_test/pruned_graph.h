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

template <class K>
Pruned_graph pruned_graph(const CGAL::Pruned_medial_axis_2<K>& p)
{
  std::map<std::size_t, int> vertex_node;
  std::vector<int> parent, degree;
  auto add = [&]() {
    parent.push_back(int(parent.size()));
    degree.push_back(0);
    return int(parent.size()) - 1;
  };
  auto node = [&](const typename CGAL::Medial_axis_2<K>::Vertex_handle& v) {
    auto it = vertex_node.find(v.id_number());
    if(it != vertex_node.end()) return it->second;
    const int n = add();
    vertex_node[v.id_number()] = n;
    return n;
  };
  std::function<int(int)> find = [&](int x) { return parent[x] == x ? x : parent[x] = find(parent[x]); };
  int edges = 0;
  for(const auto& c : p.curves()) {
    const int a = c.cut_at_begin() ? add() : node(c.halfedge.source());
    const int b = c.cut_at_end() ? add() : node(c.halfedge.target());
    ++degree[a];
    ++degree[b];
    parent[find(a)] = find(b);
    ++edges;
  }
  Pruned_graph g;
  for(int v = 0; v < int(parent.size()); ++v) {
    if(find(v) == v) ++g.components;
    if(degree[v] == 1) ++g.ends;
  }
  g.cycles = edges - int(parent.size()) + g.components;
  return g;
}

// The longest path between two ends of a pruned axis without cycles, by a
// search from every end (quadratic: for small test shapes).
template <class K>
double longest_path(const CGAL::Pruned_medial_axis_2<K>& p)
{
  std::map<std::size_t, int> vertex_node;
  std::vector<std::vector<std::pair<int, double> > > adjacent;
  auto add = [&]() {
    adjacent.emplace_back();
    return int(adjacent.size()) - 1;
  };
  auto node = [&](const typename CGAL::Medial_axis_2<K>::Vertex_handle& v) {
    auto it = vertex_node.find(v.id_number());
    if(it != vertex_node.end()) return it->second;
    const int n = add();
    vertex_node[v.id_number()] = n;
    return n;
  };
  for(const auto& c : p.curves()) {
    const int a = c.cut_at_begin() ? add() : node(c.halfedge.source());
    const int b = c.cut_at_end() ? add() : node(c.halfedge.target());
    adjacent[a].emplace_back(b, c.length());
    adjacent[b].emplace_back(a, c.length());
  }
  double longest = 0;
  const int n = int(adjacent.size());
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
