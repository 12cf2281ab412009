// Algorithm 8 against brute force: on small random multigraphs, the lexicographic minimal set
// of edges whose removal disconnects the sources from the sinks is found by enumerating every
// subset of edges. Edge i is the i-th smallest, so a subset compared as a binary number
// (bit i = edge i) is compared exactly as in the lexicographic order.
#include <CGAL/Lex_optimal_chains/Lexicographic_min_cut.h>
#include <CGAL/Random.h>

#include <cassert>
#include <cstdint>
#include <iostream>
#include <utility>
#include <vector>

namespace LOC = CGAL::Lex_optimal_chains;
using Edge = std::pair<int, int>;

bool disconnects(int n, const std::vector<Edge>& edges, std::uint32_t removed,
                 const std::vector<int>& sources, const std::vector<int>& sinks)
{
  std::vector<int> seen(n, 0), stack(sources.begin(), sources.end());
  for(int s : sources) seen[s] = 1;
  while(!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    for(std::size_t i = 0; i < edges.size(); ++i) {
      if(removed >> i & 1) continue;
      int w = -1;
      if(edges[i].first == v) w = edges[i].second;
      else if(edges[i].second == v) w = edges[i].first;
      if(w >= 0 && !seen[w]) { seen[w] = 1; stack.push_back(w); }
    }
  }
  for(int t : sinks) if(seen[t]) return false;
  return true;
}

int main()
{
  CGAL::Random rng(7);
  int graphs = 0;
  for(int trial = 0; trial < 3000; ++trial) {
    const int n = rng.get_int(2, 8);
    const int m = rng.get_int(1, 15);
    std::vector<Edge> edges; // edges[i] is the i-th smallest
    for(int i = 0; i < m; ++i) edges.emplace_back(rng.get_int(0, n), rng.get_int(0, n)); // loops and multi-edges allowed
    std::vector<int> sources{rng.get_int(0, n)}, sinks;
    if(n > 2 && rng.get_int(0, 3) == 0) sources.push_back(rng.get_int(0, n));
    do { sinks.assign(1, rng.get_int(0, n)); } while(sinks[0] == sources[0] || (sources.size() > 1 && sinks[0] == sources[1]));

    std::uint32_t best = 0;
    bool found = false;
    for(std::uint32_t s = 0; s < (1u << m) && !found; ++s) // increasing binary value = increasing lex order
      if(disconnects(n, edges, s, sources, sinks)) { best = s; found = true; }
    assert(found); // removing every edge always disconnects

    std::vector<Edge> decreasing(edges.rbegin(), edges.rend());
    std::vector<std::size_t> cut;
    LOC::lexicographic_min_cut(n, decreasing, sources, sinks, std::back_inserter(cut));
    std::uint32_t got = 0;
    for(std::size_t position : cut) got |= 1u << (m - 1 - position);
    if(got != best) std::cerr << "trial " << trial << ": got " << got << " expected " << best << "\n";
    assert(got == best);
    ++graphs;
  }

  // invalid graphs are rejected with a typed error
  const std::vector<Edge> none;
  bool thrown = false;
  try {
    std::vector<std::size_t> out;
    LOC::lexicographic_min_cut(3, none, std::vector<int>{0}, std::vector<int>{0}, std::back_inserter(out));
  }
  catch(const LOC::Input_error& e) { thrown = e.code() == LOC::Input_error_code::INVALID_GRAPH; }
  assert(thrown);
  thrown = false;
  try {
    std::vector<std::size_t> out;
    LOC::lexicographic_min_cut(3, std::vector<Edge>{{0, 5}}, std::vector<int>{0}, std::vector<int>{1}, std::back_inserter(out));
  } catch(const LOC::Input_error& e) { thrown = e.code() == LOC::Input_error_code::INVALID_GRAPH; }
  assert(thrown);
  thrown = false;
  try {
    std::vector<std::size_t> out;
    LOC::lexicographic_min_cut(3, none, std::vector<int>{}, std::vector<int>{1}, std::back_inserter(out));
  } catch(const LOC::Input_error& e) { thrown = e.code() == LOC::Input_error_code::INVALID_GRAPH; }
  assert(thrown);

  std::cout << graphs << " random graphs: Algorithm 8 equals brute force\n";
  return 0;
}
