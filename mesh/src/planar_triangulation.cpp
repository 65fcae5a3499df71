// Triangulating one simple planar polygon (a non-convex 3D wall) with CGAL's
// constrained Delaunay triangulation in the polygon's plane.

#include <queue>
#include <string>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "polygon_fan.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::mesh_detail {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fb = CGAL::Triangulation_face_base_with_info_2<int, K, CGAL::Constrained_triangulation_face_base_2<K>>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

}  // namespace

std::vector<std::array<int, 3>> triangulatePlanarLoop(std::span<const Vec3> loop, const Vec3& normal,
                                                      const char* what, Index id) {
  const Vec3 n = normal.normalized();
  const Vec3 u = n.unitOrthogonal();
  const Vec3 v = n.cross(u);  // (u, v, n) right-handed: the loop runs counter-clockwise in (u, v)
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    auto h = cdt.insert(K::Point_2(loop[i].dot(u), loop[i].dot(v)));
    h->info() = static_cast<int>(i);
    handles.push_back(h);
  }
  const auto fail = [&](const std::string& why) {
    return GeometryError(std::string(what) + " " + std::to_string(id) + " is not a simple polygon: " + why,
                         ElementId{2, id});
  };
  if (cdt.number_of_vertices() != loop.size()) throw fail("two of its vertices coincide");
  for (std::size_t i = 0; i < loop.size(); ++i) cdt.insert_constraint(handles[i], handles[(i + 1) % loop.size()]);
  if (cdt.number_of_vertices() != loop.size()) throw fail("two of its edges cross");

  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = 0;
  std::queue<Cdt::Face_handle> queue;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    Cdt::Face_handle f;
    int opposite = 0;
    if (!cdt.is_edge(handles[i], handles[(i + 1) % loop.size()], f, opposite))
      throw fail("edge " + std::to_string(i) + " is covered by another vertex");
    if (f->vertex(f->ccw(opposite)) != handles[i]) f = f->neighbor(opposite);  // the face left of i -> i+1
    if (cdt.is_infinite(f)) throw fail("its loop runs clockwise about its own normal");
    if (f->info() == 0) {
      f->info() = 1;
      queue.push(f);
    }
  }
  while (!queue.empty()) {
    auto f = queue.front();
    queue.pop();
    for (int i = 0; i < 3; ++i) {
      auto g = f->neighbor(i);
      if (f->is_constrained(i) || g->info() != 0) continue;
      if (cdt.is_infinite(g)) throw fail("its interior is not closed");
      g->info() = 1;
      queue.push(g);
    }
  }
  std::vector<std::array<int, 3>> triangles;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info() == 1) triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  if (triangles.size() + 2 != loop.size()) throw fail("it is not a single simple loop");
  return triangles;
}

}  // namespace tessella::mesh_detail
