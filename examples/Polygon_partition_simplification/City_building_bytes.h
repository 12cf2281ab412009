// The buildings of lod2_city_reconstruction() as bytes and back, so that the MPI ranks of
// lod2_reconstruct_mpi can send the buildings they modelled to the first rank. A building comes
// back as it was: its numbers bit for bit, and its meshes element for element (vertices,
// halfedges and faces in their order, each face starting at the same halfedge, with the face
// properties f:surface_type, f:building and f:plane), so that the writers give the same bytes
// as for the building itself. The ranks run one program on one kind of machine: the numbers are
// copied as they are in memory.
#ifndef LOD2_RECONSTRUCT_CITY_BUILDING_BYTES_H
#define LOD2_RECONSTRUCT_CITY_BUILDING_BYTES_H

#include <CGAL/Polygon_partition_simplification/City_building.h>
#include <CGAL/Polygon_partition_simplification/internal/CGAL_compatibility.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

class Byte_writer
{
public:
  template <class T>
  void put(const T& value)
  {
    static_assert(std::is_trivially_copyable<T>::value, "only trivially copyable values are copied as bytes");
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void put_string(const std::string& text)
  {
    put(text.size());
    bytes_ += text;
  }
  const std::string& bytes() const { return bytes_; }

private:
  std::string bytes_;
};

class Byte_reader
{
public:
  explicit Byte_reader(const std::string& bytes) : bytes_(bytes) {}
  bool at_end() const { return offset_ == bytes_.size(); }
  template <class T>
  T get()
  {
    T value;
    std::memcpy(&value, take(sizeof(T)), sizeof(T));
    return value;
  }
  std::string get_string()
  {
    const std::size_t size = get<std::size_t>();
    return std::string(take(size), size);
  }
  // an index below `count`, or `count` itself for the null element when `null_allowed`
  std::size_t get_index(std::size_t count, bool null_allowed)
  {
    const std::size_t index = get<std::size_t>();
    if(index > count || (index == count && !null_allowed)) throw std::runtime_error("the buildings of a rank arrived damaged");
    return index;
  }

private:
  const char* take(std::size_t size)
  {
    if(size > bytes_.size() - offset_) throw std::runtime_error("the buildings of a rank arrived truncated");
    const char* data = bytes_.data() + offset_;
    offset_ += size;
    return data;
  }
  const std::string& bytes_;
  std::size_t offset_ = 0;
};

// the face property `name` of `mesh` (whether it has one, then its values in the order of the faces)
template <class T, class Point>
void put_face_property(Byte_writer& out, const CGAL::Surface_mesh<Point>& mesh, const char* name)
{
  const auto map = CGAL::Polygon_partition_simplification::internal::optional_property_map(mesh.template property_map<typename CGAL::Surface_mesh<Point>::Face_index, T>(name));
  out.put(bool(map));
  if(map)
    for(auto f : mesh.faces()) out.put(T((*map)[f]));
}

template <class T, class Point>
void get_face_property(Byte_reader& in, CGAL::Surface_mesh<Point>& mesh, const char* name)
{
  if(!in.get<bool>()) return;
  auto map = mesh.template add_property_map<typename CGAL::Surface_mesh<Point>::Face_index, T>(name).first;
  for(auto f : mesh.faces()) map[f] = in.get<T>();
}

// the elements of `mesh` that are not removed, numbered in their order (a null element is
// numbered by the count of its kind)
template <class Point>
void put_mesh(Byte_writer& out, const CGAL::Surface_mesh<Point>& mesh)
{
  auto numbers = [](const auto& elements, std::size_t size) {
    std::vector<std::size_t> number(size + 1, 0);
    std::size_t next = 0;
    for(auto e : elements) number[std::size_t(e)] = next++;
    number[size] = next; // the number of the null element
    return number;
  };
  const std::vector<std::size_t> vertex = numbers(mesh.vertices(), mesh.num_vertices()),
                                 halfedge = numbers(mesh.halfedges(), mesh.num_halfedges()),
                                 face = numbers(mesh.faces(), mesh.num_faces());
  auto at = [](const std::vector<std::size_t>& number, auto e) { return e.is_valid() ? number[std::size_t(e)] : number.back(); };
  out.put(std::size_t(mesh.number_of_vertices()));
  out.put(std::size_t(mesh.number_of_halfedges()));
  out.put(std::size_t(mesh.number_of_faces()));
  for(auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    for(int i = 0; i < 3; ++i) out.put(CGAL::to_double(p[i]));
    out.put(at(halfedge, mesh.halfedge(v)));
  }
  for(auto h : mesh.halfedges()) {
    out.put(at(vertex, mesh.target(h)));
    out.put(at(halfedge, mesh.next(h)));
    out.put(at(face, mesh.face(h)));
  }
  for(auto f : mesh.faces()) out.put(at(halfedge, mesh.halfedge(f)));
  put_face_property<CGAL::Polygon_partition_simplification::Building_surface_type>(out, mesh, "f:surface_type");
  put_face_property<std::size_t>(out, mesh, "f:building");
  put_face_property<std::size_t>(out, mesh, "f:plane");
}

template <class Point>
CGAL::Surface_mesh<Point> get_mesh(Byte_reader& in)
{
  using Mesh = CGAL::Surface_mesh<Point>;
  using size_type = typename Mesh::size_type;
  const std::size_t vertices = in.get<std::size_t>(), halfedges = in.get<std::size_t>(), faces = in.get<std::size_t>();
  if(halfedges % 2 != 0) throw std::runtime_error("the buildings of a rank arrived damaged");
  Mesh mesh;
  mesh.reserve(size_type(vertices), size_type(halfedges / 2), size_type(faces));
  for(std::size_t e = 0; e < halfedges / 2; ++e) mesh.add_edge();
  for(std::size_t f = 0; f < faces; ++f) mesh.add_face();
  auto halfedge = [&](bool null_allowed) {
    const std::size_t h = in.get_index(halfedges, null_allowed);
    return h == halfedges ? mesh.null_halfedge() : typename Mesh::Halfedge_index(size_type(h));
  };
  for(std::size_t v = 0; v < vertices; ++v) {
    const double x = in.get<double>(), y = in.get<double>(), z = in.get<double>();
    const typename Mesh::Vertex_index added = mesh.add_vertex(Point(x, y, z));
    mesh.set_halfedge(added, halfedge(true));
  }
  for(std::size_t h = 0; h < halfedges; ++h) {
    const typename Mesh::Halfedge_index current{size_type(h)};
    mesh.set_target(current, typename Mesh::Vertex_index(size_type(in.get_index(vertices, false))));
    mesh.set_next(current, halfedge(false));
    const std::size_t f = in.get_index(faces, true);
    mesh.set_face(current, f == faces ? mesh.null_face() : typename Mesh::Face_index(size_type(f)));
  }
  for(std::size_t f = 0; f < faces; ++f) mesh.set_halfedge(typename Mesh::Face_index(size_type(f)), halfedge(false));
  get_face_property<CGAL::Polygon_partition_simplification::Building_surface_type>(in, mesh, "f:surface_type");
  get_face_property<std::size_t>(in, mesh, "f:building");
  get_face_property<std::size_t>(in, mesh, "f:plane");
  return mesh;
}

template <class Point>
std::string city_buildings_to_bytes(const std::vector<CGAL::Polygon_partition_simplification::City_building<Point>>& buildings)
{
  Byte_writer out;
  for(const auto& b : buildings) {
    out.put(b.id);
    out.put(b.status);
    out.put_string(b.reason);
    put_mesh(out, b.lod22);
    put_mesh(out, b.lod12);
    out.put(b.points);
    out.put(b.ground_points);
    for(double value : {b.ground_height, b.roof_height_50p, b.roof_height_70p, b.roof_height_max, b.rms_distance}) out.put(value);
    out.put(b.report);
  }
  return out.bytes();
}

// appends the buildings of `bytes` to `buildings`
template <class Point>
void city_buildings_from_bytes(const std::string& bytes,
                               std::vector<CGAL::Polygon_partition_simplification::City_building<Point>>& buildings)
{
  Byte_reader in(bytes);
  while(!in.at_end()) {
    CGAL::Polygon_partition_simplification::City_building<Point> b;
    b.id = in.get<std::size_t>();
    b.status = in.get<CGAL::Polygon_partition_simplification::Building_model_status>();
    b.reason = in.get_string();
    b.lod22 = get_mesh<Point>(in);
    b.lod12 = get_mesh<Point>(in);
    b.points = in.get<std::size_t>();
    b.ground_points = in.get<std::size_t>();
    for(double* value : {&b.ground_height, &b.roof_height_50p, &b.roof_height_70p, &b.roof_height_max, &b.rms_distance})
      *value = in.get<double>();
    b.report = in.get<CGAL::Polygon_partition_simplification::LOD2_report>();
    buildings.push_back(std::move(b));
  }
}

#endif // LOD2_RECONSTRUCT_CITY_BUILDING_BYTES_H
