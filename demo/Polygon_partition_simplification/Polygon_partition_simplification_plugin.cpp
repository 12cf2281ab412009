// The Polygon_partition_simplification plugin of CGAL's Polyhedron demo: kinetic partition of
// 2D segments and its simplification in line space.
//
// Two actions on a polylines item (2D segments: each pair of consecutive points of a polyline is
// a segment, z is ignored):
//  - "Kinetic partition": the partition of the segments inside a rectangle around them;
//  - "Simplify partition": a dialog asks for lambda1, lambda2, epsilon and the maximum angle;
//    on a partition made by this plugin, that partition is simplified; on other segments, their
//    kinetic partition is computed first (as the command-line program simplify_partition does).
// A partition is shown as two items: its edges (a polylines item) and its cells (a surface mesh
// item, one colour per cell). The numbers of lines, points and cells go to the message panel.
//
// One action on a point set item (a point cloud of buildings and the ground, z up):
//  - "LOD2 building model": lod2_building_reconstruction() of the package, with the planes of the
//    int property `segment_index` when the points have it (as CGAL's building.ply), otherwise
//    detected; the model is a surface mesh item, roofs red, walls white, floors grey.
//
// The plugin is also an IO plugin for the package's segments text file ("x0 y0 x1 y1" per line,
// '#' comments, the format of simplify_partition), loaded as a polylines item at z = 0.
//
// Scripting (the demo's QtScript, as in the headless tests): the plugin object is the global
// `polygon_partition_simplification_plugin`; its slots loadSegments(), kineticPartition(),
// simplifyPartition(), lod2Model(), lastError(), lastStatistics(), partitionStatistics() and saveSnapshot()
// run everything without a modal dialog: errors go to the message panel and to lastError().

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QFileInfo>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMainWindow>
#include <QMessageBox>
#include <QPointer>

#include "Scene_points_with_normal_item.h"
#include "Scene_polylines_item.h"
#include "Scene_surface_mesh_item.h"
#include "SMesh_type.h"

#include <CGAL/Three/Three.h>
#include <CGAL/Three/Viewer_interface.h>

#include <CGAL/Polygon_partition_simplification/IO/segments_file.h>
#include <CGAL/kinetic_partition_2.h>
#include <CGAL/lod2_building_reconstruction.h>
#include <CGAL/simplify_polygon_partition_2.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/property_map.h>

#include "ui_Polygon_partition_simplification_dialog.h"
// the interfaces of the demo built for, included here for moc, which reads the plugin's own
// includes only (see Demo_compatibility.h)
#ifdef URBAN_DEMO_CGAL_LAB
#include <CGAL/Three/CGAL_Lab_io_plugin_interface.h>
#include <CGAL/Three/CGAL_Lab_plugin_interface.h>
#else
#include <CGAL/Three/Polyhedron_demo_io_plugin_interface.h>
#include <CGAL/Three/Polyhedron_demo_plugin_interface.h>
#endif
#include "Demo_compatibility.h"
#include "View_snapshot.h"

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <queue>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace PPS = CGAL::Polygon_partition_simplification;
// The kernel of the demo's items (EPICK) is that of simplify_partition: the same doubles give
// the same partitions.
using Partition_kernel = EPICK;
using Partition = PPS::Line_partition_2<Partition_kernel>;
using Segment_2 = Partition_kernel::Segment_2;

namespace {

// The parameters of "Simplify partition", with the defaults of simplify_partition. An epsilon
// of 0 stands for the default of the CLI (1% of the half-diagonal of the partition); any other
// value, valid or not, goes to the library, which checks it.
struct Simplify_parameters
{
  double lambda1 = 0.5;
  double lambda2 = 5;
  double epsilon = 0;
  double maximum_angle = 5;
};

// The segments of a polylines item, in the order of its polylines and points (the order of the
// file it was loaded from). A polyline of one point gives no segment; z is ignored.
std::vector<Segment_2> segments_of(const Scene_polylines_item& item)
{
  std::vector<Segment_2> segments;
  for(const auto& polyline : item.polylines)
    for(std::size_t i = 1; i < polyline.size(); ++i)
      segments.emplace_back(Partition_kernel::Point_2(polyline[i - 1].x(), polyline[i - 1].y()),
                            Partition_kernel::Point_2(polyline[i].x(), polyline[i].y()));
  return segments;
}

// A new polylines item with one two-point polyline per segment, at z = 0.
template <class SegmentRange>
Scene_polylines_item* polylines_item_of(const SegmentRange& segments)
{
  Scene_polylines_item* item = new Scene_polylines_item;
  for(const Segment_2& s : segments)
    item->polylines.push_back({Partition_kernel::Point_3(s.source().x(), s.source().y(), 0),
                               Partition_kernel::Point_3(s.target().x(), s.target().y(), 0)});
  return item;
}

// The edges of a partition, as segments in input coordinates.
std::vector<Segment_2> edge_segments(const Partition& partition)
{
  std::vector<Segment_2> segments;
  for(std::size_t e = 0; e < partition.number_of_edges(); ++e) segments.push_back(partition.segment(e));
  return segments;
}

// The triangulation of one cell (a polygon with holes): a constrained Delaunay triangulation of
// its boundary, whose faces are inside when they are separated from the infinite face by an odd
// number of constrained edges (the nesting levels of CGAL's polygon triangulation example).
struct Face_nesting
{
  int level = -1;
};
using CDT_face_base = CGAL::Constrained_triangulation_face_base_2<
  Partition_kernel, CGAL::Triangulation_face_base_with_info_2<Face_nesting, Partition_kernel>>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<
  Partition_kernel, CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<Partition_kernel>, CDT_face_base>,
  CGAL::Exact_predicates_tag>;

void mark_nesting_levels(CDT& cdt)
{
  std::queue<CDT::Face_handle> next_level; // faces of the next level, across a constraint
  next_level.push(cdt.infinite_face());
  for(int level = 0; !next_level.empty(); ++level) {
    std::queue<CDT::Face_handle> queue;
    std::swap(queue, next_level);
    while(!queue.empty()) {
      const CDT::Face_handle f = queue.front();
      queue.pop();
      if(f->info().level != -1) continue;
      f->info().level = level;
      for(int i = 0; i < 3; ++i) {
        const CDT::Face_handle n = f->neighbor(i);
        if(n->info().level == -1) (cdt.is_constrained(CDT::Edge(f, i)) ? next_level : queue).push(n);
      }
    }
  }
}

// Appends the triangles of `cell` to `mesh`, at height z, with the face colour `color`.
void add_cell(const Partition::Polygon_with_holes_2& cell, double z, const CGAL::IO::Color& color, SMesh& mesh,
              SMesh::Property_map<SMesh::Face_index, CGAL::IO::Color>& colors)
{
  CDT cdt;
  cdt.insert_constraint(cell.outer_boundary().vertices_begin(), cell.outer_boundary().vertices_end(), true);
  for(auto h = cell.holes_begin(); h != cell.holes_end(); ++h)
    cdt.insert_constraint(h->vertices_begin(), h->vertices_end(), true);
  mark_nesting_levels(cdt);
  std::map<CDT::Vertex_handle, SMesh::Vertex_index> vertex_of;
  auto vertex = [&](CDT::Vertex_handle v) {
    auto [it, inserted] = vertex_of.emplace(v, SMesh::Vertex_index());
    if(inserted) it->second = mesh.add_vertex(Partition_kernel::Point_3(v->point().x(), v->point().y(), z));
    return it->second;
  };
  for(const CDT::Face_handle f : cdt.finite_face_handles()) {
    if(f->info().level % 2 != 1) continue;
    const SMesh::Face_index face = mesh.add_face(vertex(f->vertex(0)), vertex(f->vertex(1)), vertex(f->vertex(2)));
    if(face != SMesh::null_face()) colors[face] = color;
  }
}

// The colour of cell `c`: light colours as those of the demo's compute_color_map() (Color_map.h),
// with hues in steps of the golden ratio rather than in order, so that consecutive cells (often
// neighbours) differ, and saturations that do not depend on std::rand() (same image every run).
QColor cell_color(std::size_t c)
{
  const double hue = std::fmod(0.61803398874989485 * double(c), 1.0);
  return QColor::fromHsvF(hue, 0.35 + 0.2 * double(c % 3), 1.0);
}

// The cells of a valid partition as a surface mesh: each cell triangulated on its own (cells
// share no vertex, so each cell is one connected component), all its faces of one colour.
// The cells are at z = -1e-3 times the half-diagonal, just below the edges (at z = 0), so that
// the edges are not hidden by the faces in the view.
SMesh* cells_mesh(const Partition& partition)
{
  std::vector<Partition::Polygon_with_holes_2> cells;
  partition.cells(std::back_inserter(cells));
  std::unique_ptr<SMesh> mesh(new SMesh);
  auto colors = mesh->add_property_map<SMesh::Face_index, CGAL::IO::Color>("f:color").first;
  const double z = -1e-3 * partition.frame().scale;
  for(std::size_t c = 0; c < cells.size(); ++c) {
    const QColor q = cell_color(c);
    add_cell(cells[c], z, CGAL::IO::Color(q.red(), q.green(), q.blue()), *mesh, colors);
  }
  return mesh.release();
}

// The number of distinct face colours of a mesh with an "f:color" map (0 without one).
std::size_t number_of_colors(const SMesh& mesh)
{
  const auto map = Urban_demo::found_property_map(mesh.property_map<SMesh::Face_index, CGAL::IO::Color>("f:color"));
  if(!map) return 0;
  std::set<std::array<unsigned char, 3>> colors;
  for(const SMesh::Face_index f : mesh.faces()) {
    const CGAL::IO::Color c = (*map)[f];
    colors.insert({c.red(), c.green(), c.blue()});
  }
  return colors.size();
}

// The statistics of a simplification, with the keys and values of `simplify_partition --json`
// (but the timings).
QJsonObject simplification_json(std::size_t segments, const PPS::Simplification_statistics& s)
{
  QJsonObject j;
  j["segments"] = qint64(segments);
  j["lines_before"] = qint64(s.lines_before);
  j["lines_after"] = qint64(s.lines_after);
  j["points_before"] = qint64(s.points_before);
  j["points_after"] = qint64(s.points_after);
  j["cells_before"] = qint64(s.cells_before);
  j["cells_after"] = qint64(s.cells_after);
  j["orthogonal_pairs_before"] = qint64(s.orthogonal_pairs_before);
  j["orthogonal_pairs_after"] = qint64(s.orthogonal_pairs_after);
  j["iterations"] = qint64(s.iterations);
  j["rounds"] = qint64(s.rounds);
  j["line_merges"] = qint64(s.line_merges);
  j["point_merges"] = qint64(s.point_merges);
  j["removed_points"] = qint64(s.removed_points);
  j["far_points"] = qint64(s.far_points);
  j["far_point_removals"] = qint64(s.far_point_removals);
  j["rejected_rounds"] = qint64(s.rejected_rounds);
  return j;
}

QString compact(const QJsonObject& j) { return QString::fromUtf8(QJsonDocument(j).toJson(QJsonDocument::Compact)); }

} // namespace

// The dialog of "Simplify partition".
class Polygon_partition_simplification_dialog : public QDialog, private Ui::PolygonPartitionSimplificationDialog
{
public:
  explicit Polygon_partition_simplification_dialog(QWidget* parent) : QDialog(parent) { setupUi(this); }

  Simplify_parameters parameters() const
  {
    Simplify_parameters p;
    p.lambda1 = lambda1SpinBox->value();
    p.lambda2 = lambda2SpinBox->value();
    p.epsilon = epsilonSpinBox->value(); // 0: "Automatic"
    p.maximum_angle = angleSpinBox->value();
    return p;
  }
};

class Polyhedron_demo_polygon_partition_simplification_plugin
  : public QObject,
    public Urban_demo::Plugin_helper,
    public Urban_demo::Io_plugin_interface
{
  Q_OBJECT
#ifdef URBAN_DEMO_CGAL_LAB // see Demo_compatibility.h
  Q_INTERFACES(CGAL::Three::CGAL_Lab_plugin_interface CGAL::Three::CGAL_Lab_io_plugin_interface)
  Q_PLUGIN_METADATA(IID "com.geometryfactory.CGALLab.PluginInterface/1.0")
  Q_PLUGIN_METADATA(IID "com.geometryfactory.CGALLab.IOPluginInterface/1.90")
#else
  Q_INTERFACES(CGAL::Three::Polyhedron_demo_plugin_interface CGAL::Three::Polyhedron_demo_io_plugin_interface)
  Q_PLUGIN_METADATA(IID "com.geometryfactory.PolyhedronDemo.PluginInterface/1.0")
  Q_PLUGIN_METADATA(IID "com.geometryfactory.PolyhedronDemo.IOPluginInterface/1.90")
#endif

public:
  using Item_id = CGAL::Three::Scene_interface::Item_id;

  using Urban_demo::Io_plugin_interface::init;
  void init(QMainWindow* mainWindow, CGAL::Three::Scene_interface* scene_interface, Messages_interface*) override
  {
    scene = scene_interface;
    mw = mainWindow;
    actionKinetic = new QAction(tr("Kinetic partition"), mw);
    actionKinetic->setObjectName("actionKineticPartition");
    actionKinetic->setProperty("subMenuName", "Operations on Polylines/Polygon Partition");
    actionSimplify = new QAction(tr("Simplify partition"), mw);
    actionSimplify->setObjectName("actionSimplifyPartition");
    actionSimplify->setProperty("subMenuName", "Operations on Polylines/Polygon Partition");
    actionLod2 = new QAction(tr("LOD2 building model"), mw);
    actionLod2->setObjectName("actionLod2BuildingModel");
    actionLod2->setProperty("subMenuName", "Point Set Processing/Building Reconstruction");
    autoConnectActions();
  }

  bool applicable(QAction* action) const override
  {
    CGAL::Three::Scene_item* item = scene->item(scene->mainSelectionIndex());
    if(action == actionLod2) return qobject_cast<Scene_points_with_normal_item*>(item) != nullptr;
    if(action == actionSimplify && partitions.count(item) > 0) return true; // its cells item too
    return qobject_cast<Scene_polylines_item*>(item) != nullptr;
  }

  QList<QAction*> actions() const override
  {
    return QList<QAction*>() << actionKinetic << actionSimplify << actionLod2;
  }

  // IO: the segments text file of the package (the extension of its data, .txt; the files of
  // the demo's other .txt formats are left to their plugins).
  QString name() const override { return "segments_2_io_plugin"; }
  QString nameFilters() const override { return "2D segments, x0 y0 x1 y1 per line (*.txt)"; }
  bool canLoad(QFileInfo fileinfo) const override;
  QList<CGAL::Three::Scene_item*> load(QFileInfo fileinfo, bool& ok, bool add_to_scene = true) override;
  bool canSave(const CGAL::Three::Scene_item*) override { return false; }
  bool save(QFileInfo, QList<CGAL::Three::Scene_item*>&) override { return false; }

public Q_SLOTS:
  void on_actionKineticPartition_triggered() { kinetic(scene->mainSelectionIndex(), true); }
  void on_actionSimplifyPartition_triggered();
  void on_actionLod2BuildingModel_triggered() { lod2(scene->mainSelectionIndex(), true); }

  // Scripting: each returns the index of the new item (the edges of a partition), or -1 with the
  // reason in lastError().
  int loadSegments(const QString& file);
  int kineticPartition(int item) { return kinetic(item, false); }
  // epsilon = 0: 1% of the half-diagonal of the partition (simplify_partition without --epsilon)
  int simplifyPartition(int item, double lambda1 = 0.5, double lambda2 = 5, double epsilon = 0,
                        double maximum_angle = 5)
  {
    return simplify(item, Simplify_parameters{lambda1, lambda2, epsilon, maximum_angle}, false);
  }

  // the LOD2 model of a point set item (the surface mesh item), as lod2_reconstruct computes it
  int lod2Model(int item) { return lod2(item, false); }

  // the reason why the last call made no item ("" after a success)
  QString lastError() const { return last_error; }
  // the statistics of the last successful kinetic partition or simplification, one JSON line
  // (those of simplify_partition --json for a simplification) with the index of the cells item
  QString lastStatistics() const { return last_statistics; }
  // whether an item is shown (a script must not hold `scene.item(i)`: CGAL Lab's script engine
  // takes the item and deletes it when the demo quits)
  bool itemVisible(int item) const { return scene->item(item) && scene->item(item)->visible(); }
  QString partitionStatistics(int item) const;
  bool saveSnapshot(const QString& file);

private:
  // A partition made by this plugin, and its two items (the edges, the cells; null once the
  // user has deleted one of them).
  struct Record
  {
    std::shared_ptr<const Partition> partition;
    std::size_t segments = 0; // the input segments of the kinetic partition
    QPointer<CGAL::Three::Scene_item> edges;
    QPointer<CGAL::Three::Scene_item> cells;
  };

  Scene_polylines_item* read_item(const QFileInfo& fileinfo);
  int kinetic(Item_id id, bool interactive);
  int simplify(Item_id id, const Simplify_parameters& p, bool interactive);
  int lod2(Item_id id, bool interactive);
  Item_id add_partition(const Partition& partition, std::size_t segments, const QString& name, Item_id& cells_id);
  void hide_source(Item_id id);
  int fail(const QString& reason, bool interactive);

  QAction* actionKinetic = nullptr;
  QAction* actionSimplify = nullptr;
  QAction* actionLod2 = nullptr;
  // by edges item and by cells item; an entry goes when its item is deleted
  std::map<const CGAL::Three::Scene_item*, std::shared_ptr<Record>> partitions;
  QString last_error, last_statistics;
}; // end Polyhedron_demo_polygon_partition_simplification_plugin

using Plugin = Polyhedron_demo_polygon_partition_simplification_plugin;

// A segments file: the first line that is not blank nor a comment has four numbers. The files
// of the demo's other formats ending in .txt are left to their plugins.
bool Plugin::canLoad(QFileInfo fileinfo) const
{
  const QString file = fileinfo.fileName().toLower();
  if(!file.endsWith(".txt")) return false;
  for(const char* other : {".polylines.txt", ".camera.txt", ".selection.txt"})
    if(file.endsWith(other)) return false;
  std::ifstream in(fileinfo.filePath().toStdString());
  std::string line;
  while(std::getline(in, line)) {
    std::istringstream is(line);
    std::string first, rest;
    if(!(is >> first) || first[0] == '#') continue;
    is.str(line);
    is.clear();
    double c[4];
    return (is >> c[0] >> c[1] >> c[2] >> c[3]) && !(is >> rest);
  }
  return in.eof(); // an empty file is an empty set of segments
}

// Reads a segments file into a new polylines item (one two-point polyline per segment, z = 0),
// or returns null with the reason in last_error.
Scene_polylines_item* Plugin::read_item(const QFileInfo& fileinfo)
{
  std::vector<Segment_2> segments;
  try {
    segments = PPS::IO::read_segments_2<Partition_kernel>(fileinfo.filePath().toStdString());
  } catch(const std::exception& e) {
    last_error = QString::fromStdString(e.what());
    return nullptr;
  }
  last_error.clear();
  Scene_polylines_item* item = polylines_item_of(segments);
  item->setName(fileinfo.completeBaseName());
  item->setColor(Qt::red);
  item->invalidateOpenGLBuffers();
  return item;
}

// File > Open: on an error, the reason goes to the message panel (the demo then says in a
// message box that the file could not be loaded).
QList<CGAL::Three::Scene_item*> Plugin::load(QFileInfo fileinfo, bool& ok, bool add_to_scene)
{
  Scene_polylines_item* item = read_item(fileinfo);
  ok = item != nullptr;
  if(!ok) {
    CGAL::Three::Three::error(last_error);
    return {};
  }
  if(add_to_scene) scene->addItem(item);
  return {item};
}

// Scripting: the index of the new polylines item, or -1 (reason in lastError(); no message box).
int Plugin::loadSegments(const QString& file)
{
  Scene_polylines_item* item = read_item(QFileInfo(file));
  if(item == nullptr) return fail(last_error, false);
  return scene->addItem(item);
}

void Plugin::on_actionSimplifyPartition_triggered()
{
  Polygon_partition_simplification_dialog dialog(mw);
  if(dialog.exec() != QDialog::Accepted) return;
  simplify(scene->mainSelectionIndex(), dialog.parameters(), true);
}

// The library's one-line reason: a message box when a user clicked the action, the message
// panel (and lastError()) only when a script called (a modal box would block the script).
int Plugin::fail(const QString& reason, bool interactive)
{
  last_error = reason;
  std::cerr << "Polygon_partition_simplification: " << reason.toStdString() << std::endl;
  CGAL::Three::Three::error(reason);
  if(interactive) QMessageBox::warning(mw, tr("Polygon partition"), reason);
  return -1;
}

// Adds the edges and the cells of a valid partition to the scene; returns the edges item (and
// the cells item in `cells_id`).
Plugin::Item_id Plugin::add_partition(const Partition& partition, std::size_t segments, const QString& name,
                                      Item_id& cells_id)
{
  auto record = std::make_shared<Record>();
  record->partition = std::make_shared<const Partition>(partition);
  record->segments = segments;
  Scene_polylines_item* edges = polylines_item_of(edge_segments(partition));
  edges->setName(name);
  edges->setColor(Qt::black);
  edges->invalidateOpenGLBuffers();
  Scene_surface_mesh_item* cells = new Scene_surface_mesh_item(cells_mesh(partition));
  cells->setName(tr("%1 (cells)").arg(name));
  cells->setRenderingMode(Flat); // the triangles are no edges of the partition
  cells->invalidateOpenGLBuffers();
  record->edges = edges;
  record->cells = cells;
  for(CGAL::Three::Scene_item* item : {static_cast<CGAL::Three::Scene_item*>(edges),
                                        static_cast<CGAL::Three::Scene_item*>(cells)}) {
    partitions[item] = record;
    connect(item, &QObject::destroyed, this, [this, item] { partitions.erase(item); });
  }
  cells_id = scene->addItem(cells);
  return scene->addItem(edges);
}

// Hides what a new partition replaces in the view: the segments, or both items of a partition.
void Plugin::hide_source(Item_id id)
{
  CGAL::Three::Scene_item* item = scene->item(id);
  const auto it = partitions.find(item);
  std::vector<CGAL::Three::Scene_item*> items{item};
  if(it != partitions.end()) items = {it->second->edges, it->second->cells};
  for(CGAL::Three::Scene_item* i : items) {
    if(i == nullptr) continue; // deleted
    i->setVisible(false);
    scene->itemChanged(i);
  }
}

// Runs the kinetic partition of the segments of a polylines item. The scene changes only on
// success (two new items, the segments hidden).
int Plugin::kinetic(Item_id id, bool interactive)
{
  last_error.clear();
  const auto* item = qobject_cast<Scene_polylines_item*>(scene->item(id));
  if(item == nullptr) return fail(tr("the kinetic partition needs a polylines item (2D segments)"), interactive);
  const std::vector<Segment_2> segments = segments_of(*item);
  Partition partition;
  double seconds = 0;
  QApplication::setOverrideCursor(Qt::WaitCursor);
  try {
    const auto start = std::chrono::steady_clock::now();
    partition = CGAL::kinetic_partition_2(segments);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  } catch(const PPS::Input_error& e) {
    QApplication::restoreOverrideCursor();
    return fail(QString::fromStdString(e.what()), interactive);
  } catch(const std::exception& e) { // not an input error: a bug, reported rather than a crash
    QApplication::restoreOverrideCursor();
    return fail(tr("unexpected error: %1").arg(e.what()), interactive);
  }
  QApplication::restoreOverrideCursor();
  // (rare: nearly identical crossing lines; the simplification would refuse it too)
  const std::string defect = partition.defect();
  if(!defect.empty()) return fail(tr("the partition is not valid: %1").arg(QString::fromStdString(defect)), interactive);

  const std::size_t cells = partition.number_of_cells();
  Item_id cells_id = -1;
  const Item_id edges =
    add_partition(partition, segments.size(), tr("%1 (kinetic partition)").arg(item->name()), cells_id);
  hide_source(id);
  QJsonObject j;
  j["segments"] = qint64(segments.size());
  j["lines"] = qint64(partition.number_of_lines());
  j["points"] = qint64(partition.number_of_vertices());
  j["edges"] = qint64(partition.number_of_edges());
  j["cells"] = qint64(cells);
  j["cells_item"] = cells_id;
  last_statistics = compact(j);
  CGAL::Three::Three::information(tr("Kinetic partition of %1: %2 segments, %3 lines, %4 points, %5 edges, %6 cells "
                                     "(%7 s)").arg(item->name()).arg(segments.size()).arg(partition.number_of_lines())
                                    .arg(partition.number_of_vertices()).arg(partition.number_of_edges()).arg(cells)
                                    .arg(seconds));
  return edges;
}

// Simplifies the partition of an item (made by this plugin), or the kinetic partition of the
// segments of another polylines item, with the calls of simplify_partition. The scene changes
// only on success (two new items, the input hidden).
int Plugin::simplify(Item_id id, const Simplify_parameters& p, bool interactive)
{
  last_error.clear();
  CGAL::Three::Scene_item* item = scene->item(id);
  const auto record = partitions.find(item);
  const auto* polylines = qobject_cast<Scene_polylines_item*>(item);
  if(record == partitions.end() && polylines == nullptr)
    return fail(tr("the simplification needs a partition or a polylines item (2D segments)"), interactive);
  std::size_t segments = 0;
  Partition partition;
  PPS::Simplification_statistics stats;
  QApplication::setOverrideCursor(Qt::WaitCursor);
  try {
    if(record != partitions.end()) {
      partition = *record->second->partition;
      segments = record->second->segments;
    } else {
      const std::vector<Segment_2> input = segments_of(*polylines);
      segments = input.size();
      partition = CGAL::kinetic_partition_2(input);
    }
    const double epsilon = p.epsilon == 0 ? 0.01 * partition.frame().scale : p.epsilon;
    stats = CGAL::simplify_polygon_partition_2(
      partition, PPS::parameters::concurrency_weight(p.lambda1,
                 PPS::parameters::orthogonality_weight(p.lambda2,
                 PPS::parameters::collapse_distance(epsilon,
                 PPS::parameters::maximum_angle(p.maximum_angle)))));
  } catch(const PPS::Input_error& e) {
    QApplication::restoreOverrideCursor();
    return fail(QString::fromStdString(e.what()), interactive);
  } catch(const std::exception& e) { // not an input error: a bug, reported rather than a crash
    QApplication::restoreOverrideCursor();
    return fail(tr("unexpected error: %1").arg(e.what()), interactive);
  }
  QApplication::restoreOverrideCursor();

  const QString base = record != partitions.end() && record->second->edges ? record->second->edges->name()
                                                                            : item->name();
  Item_id cells_id = -1;
  const Item_id edges = add_partition(partition, segments, tr("%1 (simplified)").arg(base), cells_id);
  hide_source(id);
  QJsonObject j = simplification_json(segments, stats);
  j["cells_item"] = cells_id;
  last_statistics = compact(j);
  CGAL::Three::Three::information(
    tr("Simplify partition of %1 (lambda1 %2, lambda2 %3, epsilon %4, maximum angle %5): lines %6 -> %7, "
       "cells %8 -> %9, points %10 -> %11, orthogonal pairs %12 -> %13; %14 rounds, %15 gradient steps, %16 s")
      .arg(base).arg(p.lambda1).arg(p.lambda2).arg(p.epsilon == 0 ? tr("automatic") : QString::number(p.epsilon))
      .arg(p.maximum_angle).arg(stats.lines_before).arg(stats.lines_after).arg(stats.cells_before)
      .arg(stats.cells_after).arg(stats.points_before).arg(stats.points_after).arg(stats.orthogonal_pairs_before)
      .arg(stats.orthogonal_pairs_after).arg(stats.rounds).arg(stats.iterations).arg(stats.seconds));
  return edges;
}

// Scripting: one JSON line about an item of a partition made by this plugin: its lines, points,
// edges and cells, and for the cells item its faces, connected components (one per cell) and
// face colours; "" for another item.
QString Plugin::partitionStatistics(int item) const
{
  const CGAL::Three::Scene_item* scene_item = scene->item(item);
  const auto record = partitions.find(scene_item);
  if(record == partitions.end()) return QString();
  const Partition& partition = *record->second->partition;
  QJsonObject j;
  j["segments"] = qint64(record->second->segments);
  j["lines"] = qint64(partition.number_of_lines());
  j["points"] = qint64(partition.number_of_vertices());
  j["edges"] = qint64(partition.number_of_edges());
  j["cells"] = qint64(partition.number_of_cells());
  if(const auto* polylines = qobject_cast<const Scene_polylines_item*>(scene_item))
    j["polylines"] = qint64(polylines->polylines.size());
  if(const auto* mesh_item = qobject_cast<const Scene_surface_mesh_item*>(scene_item)) {
    const SMesh& mesh = *mesh_item->face_graph();
    std::vector<std::size_t> component(mesh.num_faces()); // indexed by face index
    j["faces"] = qint64(mesh.number_of_faces());
    j["components"] = qint64(CGAL::Polygon_mesh_processing::connected_components(mesh, CGAL::make_property_map(component)));
    j["colors"] = qint64(number_of_colors(mesh));
  }
  return compact(j);
}

// Scripting: writes the main 3D view to an image file (see demo/common/View_snapshot.h).
bool Plugin::saveSnapshot(const QString& file)
{
  if(save_view_snapshot(file, last_error)) return true;
  std::cerr << "Polygon_partition_simplification: " << last_error.toStdString() << std::endl;
  return false;
}

#include "Polygon_partition_simplification_plugin.moc"

// The LOD2 model of the points of a point set item: a new surface mesh item, its faces
// coloured by type; the statistics of lod2_reconstruct --json in lastStatistics().
int Plugin::lod2(Item_id id, bool interactive)
{
  const auto* points_item = qobject_cast<Scene_points_with_normal_item*>(scene->item(id));
  if(points_item == nullptr) return fail(tr("LOD2 building model: select a point set item"), interactive);
  const Point_set& points = *points_item->point_set();
  SMesh model;
  PPS::LOD2_report report;
  QApplication::setOverrideCursor(Qt::WaitCursor);
  try {
    auto np = CGAL::parameters::point_map(points.point_map());
    const auto plane_index = Urban_demo::found_property_map(points.property_map<int>("segment_index"));
    if(points.has_normal_map() && plane_index)
      report = CGAL::lod2_building_reconstruction(points, model, np.normal_map(points.normal_map()).plane_index_map(*plane_index));
    else if(points.has_normal_map())
      report = CGAL::lod2_building_reconstruction(points, model, np.normal_map(points.normal_map()));
    else if(plane_index)
      report = CGAL::lod2_building_reconstruction(points, model, np.plane_index_map(*plane_index));
    else
      report = CGAL::lod2_building_reconstruction(points, model, np);
  } catch(const std::exception& e) {
    QApplication::restoreOverrideCursor();
    return fail(QString::fromStdString(e.what()), interactive);
  }
  QApplication::restoreOverrideCursor();
  const auto type = *Urban_demo::found_property_map(model.property_map<SMesh::Face_index, PPS::Building_surface_type>("f:surface_type"));
  auto color = model.add_property_map<SMesh::Face_index, CGAL::IO::Color>("f:color").first;
  for(auto f : model.faces())
    color[f] = type[f] == PPS::Building_surface_type::ROOF   ? CGAL::IO::Color(200, 60, 50)
               : type[f] == PPS::Building_surface_type::WALL ? CGAL::IO::Color(235, 235, 225)
                                                             : CGAL::IO::Color(120, 120, 120);
  QJsonObject statistics;
  statistics["points"] = qint64(report.points);
  statistics["planes"] = qint64(report.planes);
  statistics["segments"] = qint64(report.segments);
  statistics["cells_before"] = qint64(report.cells_before);
  statistics["cells_after"] = qint64(report.cells_after);
  statistics["buildings"] = qint64(report.buildings);
  statistics["faces"] = qint64(report.faces);
  statistics["closed"] = report.closed;
  statistics["bounds_volume"] = report.bounds_volume;
  statistics["total_s"] = report.seconds;
  Scene_surface_mesh_item* item = new Scene_surface_mesh_item(model);
  item->setName(tr("%1 (LOD2)").arg(points_item->name()));
  item->invalidateOpenGLBuffers();
  const Item_id result = scene->addItem(item);
  statistics["item"] = result;
  last_statistics = QString::fromUtf8(QJsonDocument(statistics).toJson(QJsonDocument::Compact));
  last_error.clear();
  CGAL::Three::Three::information(tr("LOD2 building model: %1 building(s), %2 faces, %3, cells %4 -> %5, %6 s")
                                    .arg(report.buildings).arg(report.faces)
                                    .arg(report.closed ? tr("closed") : tr("NOT closed"))
                                    .arg(report.cells_before).arg(report.cells_after).arg(report.seconds));
  return result;
}
