// The shape of a pruned medial axis as a graph (test-only code): its nodes
// are the kept vertices and the cut ends of curves, its edges the kept
// curves.  Counts its ends (nodes of degree 1), components and independent
// cycles.

#ifndef PMA_TEST_PRUNED_GRAPH_H
#define PMA_TEST_PRUNED_GRAPH_H

#include <CGAL/Progressive_medial_axis_2/Medial_axis_significance_2.h>

#include <cstddef>
#include <functional>
#include <map>
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

} // namespace pma_test

#endif // PMA_TEST_PRUNED_GRAPH_H
