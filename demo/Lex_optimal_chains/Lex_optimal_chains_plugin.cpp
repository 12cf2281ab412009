// The Lex_optimal_chains plugin of CGAL's Polyhedron demo: surface reconstruction of a point
// set item as a lexicographic optimal chain of its Delaunay triangulation.
//
// Two actions on a point set item:
//  - "Closed surface (lexicographic)": the interior is found automatically (the most persistent
//    void), or given by the points of another selected point set item;
//  - "Open surface (lexicographic)": the surface bounded by the closed polylines of a selected
//    polylines item, or by the automatic footprint polygon (terrain tiles), over Q or Z2.
// The result is a new surface mesh item; the statistics of the report go to the message panel.
// A progress dialog shows the stages and can cancel (the scene is then left unchanged).
//
// Scripting (the demo's QtScript, as in the headless tests): the plugin object is the global
// `lex_optimal_chains_plugin`; its slots closedSurface(), openSurface(), lastError(),
// meshStatistics(), saveSnapshot() and setCancelAt() run everything without a modal dialog:
// errors go to the message panel and to lastError() instead of a message box.

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMainWindow>
#include <QMessageBox>
#include <QProgressDialog>
#include <QThread>

#include "Scene_points_with_normal_item.h"
#include "Scene_polylines_item.h"
#include "Scene_surface_mesh_item.h"
#include "SMesh_type.h"

#include <CGAL/Three/Polyhedron_demo_plugin_helper.h>
#include <CGAL/Three/Polyhedron_demo_plugin_interface.h>
#include <CGAL/Three/Three.h>
#include <CGAL/Three/Viewer_interface.h>

#include <CGAL/lex_optimal_closed_surface.h>
#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/Lex_optimal_chains/footprint_boundary.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/property_map.h>

#include "ui_Lex_optimal_chains_dialog.h"
#include "View_snapshot.h"

#include <functional>
#include <iostream>
#include <memory>
#include <vector>

namespace LOC = CGAL::Lex_optimal_chains;
using Point = EPICK::Point_3;

namespace {

// What to reconstruct: filled by the dialog, or by the arguments of a script call.
struct Lex_request
{
  bool closed = true;
  CGAL::Three::Scene_interface::Item_id points_item = -1;
  CGAL::Three::Scene_interface::Item_id interior_item = -1; // closed: -1 for the automatic interior
  CGAL::Three::Scene_interface::Item_id boundary_item = -1; // open: -1 for the footprint polygon
  double min_persistence = 0;                               // closed, automatic interior: 0 for "stands out"
  bool robust = false;                                      // closed: smooth noisy points first
  bool rational = true;                                     // open: Q (oriented) or Z2
  bool remove_blocking = false;                             // open
  bool keep_non_manifold = false;
};

// The topology of a result mesh, with the definitions of `lex_reconstruct --json` so that the
// tests can compare the two: genus = sum over the components of (2 - chi - border loops) / 2.
struct Mesh_statistics
{
  std::size_t vertices = 0, faces = 0, components = 0, border_edges = 0, border_loops = 0;
  long genus = 0;
  bool closed = false;
};

Mesh_statistics mesh_statistics(const SMesh& mesh)
{
  Mesh_statistics s;
  s.vertices = mesh.number_of_vertices();
  s.faces = mesh.number_of_faces();
  std::vector<std::size_t> component(mesh.num_faces()); // indexed by face index
  s.components = CGAL::Polygon_mesh_processing::connected_components(mesh, CGAL::make_property_map(component));
  std::vector<bool> seen(mesh.num_halfedges(), false);
  for(const SMesh::Halfedge_index h : mesh.halfedges()) {
    if(!mesh.is_border(h)) continue;
    ++s.border_edges;
    if(seen[h]) continue;
    ++s.border_loops;
    for(SMesh::Halfedge_index g = h; !seen[g]; g = mesh.next(g)) seen[g] = true;
  }
  const long chi = long(mesh.number_of_vertices()) - long(mesh.number_of_edges()) + long(mesh.number_of_faces());
  s.genus = (2 * long(s.components) - chi - long(s.border_loops)) / 2;
  s.closed = s.border_edges == 0 && s.faces > 0;
  return s;
}

// The points of a point set item (all of them: a selection in the item is ignored). They are
// copied so that the item may change while the progress dialog processes events.
std::vector<Point> points_of(const Scene_points_with_normal_item& item)
{
  const Point_set& set = *item.point_set();
  std::vector<Point> points;
  points.reserve(set.size());
  for(Point_set::const_iterator it = set.begin(); it != set.end(); ++it) points.push_back(set.point(*it));
  return points;
}

// The progress dialog of a run, driven by the library's progress callback (on this thread:
// the computation runs in the callback's caller, so the events are processed here, at most
// every 100 ms). It shows the stage; Cancel makes the callback return false, on which the
// library throws Input_error(CANCELLED) before it modifies the output mesh. `cancel_at`
// (scripts only, for the tests) presses Cancel when the progress reaches it.
class Progress
{
public:
  Progress(QWidget* parent, const QString& title, double cancel_at)
    : dialog_(title, QObject::tr("Cancel"), 0, 100, parent), cancel_at_(cancel_at)
  {
    dialog_.setWindowTitle(title);
    dialog_.setWindowModality(Qt::WindowModal); // the scene cannot be edited meanwhile
    dialog_.setMinimumDuration(0);
    dialog_.setAutoClose(false);
    dialog_.setAutoReset(false);
    dialog_.show();
    update(0.0);
  }

  bool operator()(double x)
  {
    if(cancel_at_ >= 0 && x >= cancel_at_) dialog_.cancel(); // what a click on Cancel does
    if(x == 0.0 || x >= 1.0 || !timer_.isValid() || timer_.elapsed() > 100) update(x);
    return !dialog_.wasCanceled();
  }

  std::function<bool(double)> callback() { return [this](double x) { return (*this)(x); }; }

private:
  void update(double x)
  {
    // The library documents the progress as a fraction only: the stages below are what its
    // calls at 0 (before the triangulation) and 1 (before the mesh is written) mean.
    dialog_.setLabelText(x <= 0.0 ? QObject::tr("Delaunay triangulation...")
                         : x < 1.0 ? QObject::tr("Lexicographic optimal chain... %1%").arg(int(100 * x))
                                   : QObject::tr("Building the mesh..."));
    dialog_.setValue(int(100 * x));
    QApplication::processEvents();
    timer_.start();
  }

  QProgressDialog dialog_;
  QElapsedTimer timer_;
  double cancel_at_;
};

} // namespace

// The dialog of both actions: the group box of the other action is hidden.
class Lex_optimal_chains_dialog : public QDialog, private Ui::LexOptimalChainsDialog
{
public:
  using Item_list = QList<QPair<CGAL::Three::Scene_interface::Item_id, QString>>;

  Lex_optimal_chains_dialog(QWidget* parent, bool closed, const Item_list& candidates) : QDialog(parent)
  {
    setupUi(this);
    setWindowTitle(closed ? tr("Closed surface (lexicographic)") : tr("Open surface (lexicographic)"));
    (closed ? openBox : closedBox)->hide();
    QComboBox* combo = closed ? interiorCombo : boundaryCombo;
    combo->addItem(closed ? tr("Automatic (most persistent void)") : tr("Automatic (footprint polygon)"), -1);
    for(const auto& c : candidates) combo->addItem(c.second, c.first);
  }

  void fill(Lex_request& r) const
  {
    r.interior_item = interiorCombo->currentData().toInt();
    r.boundary_item = boundaryCombo->currentData().toInt();
    r.min_persistence = persistenceSpinBox->value();
    r.robust = robustCheckBox->isChecked();
    r.rational = qRadioButton->isChecked();
    r.remove_blocking = removeBlockingCheckBox->isChecked();
    r.keep_non_manifold = keepNonManifoldCheckBox->isChecked();
  }
};

class Polyhedron_demo_lex_optimal_chains_plugin : public QObject, public CGAL::Three::Polyhedron_demo_plugin_helper
{
  Q_OBJECT
  Q_INTERFACES(CGAL::Three::Polyhedron_demo_plugin_interface)
  Q_PLUGIN_METADATA(IID "com.geometryfactory.PolyhedronDemo.PluginInterface/1.0")

public:
  void init(QMainWindow* mainWindow, CGAL::Three::Scene_interface* scene_interface, Messages_interface*) override
  {
    scene = scene_interface;
    mw = mainWindow;
    actionClosed = new QAction(tr("Closed surface (lexicographic)"), mw);
    actionClosed->setObjectName("actionLexClosedSurface");
    actionClosed->setProperty("subMenuName", "Point Set Processing/Surface Reconstruction");
    actionOpen = new QAction(tr("Open surface (lexicographic)"), mw);
    actionOpen->setObjectName("actionLexOpenSurface");
    actionOpen->setProperty("subMenuName", "Point Set Processing/Surface Reconstruction");
    autoConnectActions();
  }

  bool applicable(QAction*) const override
  {
    return qobject_cast<Scene_points_with_normal_item*>(scene->item(scene->mainSelectionIndex())) != nullptr;
  }

  QList<QAction*> actions() const override { return QList<QAction*>() << actionClosed << actionOpen; }

public Q_SLOTS:
  void on_actionLexClosedSurface_triggered() { run_from_dialog(true); }
  void on_actionLexOpenSurface_triggered() { run_from_dialog(false); }

  // Scripting: the index of the new surface mesh item, or -1 (reason in lastError()).
  // interior_item: a point set item, or -1 for the automatic interior; min_persistence 0
  // accepts it when it stands out from the other voids (the library's default); robust
  // smooths noisy points first.
  int closedSurface(int points_item, int interior_item = -1, double min_persistence = 0, bool robust = false)
  {
    Lex_request r;
    r.closed = true;
    r.points_item = points_item;
    r.interior_item = interior_item;
    r.min_persistence = min_persistence;
    r.robust = robust;
    return run(r, false);
  }

  // Scripting: boundary_item is a polylines item, or -1 for the automatic footprint polygon;
  // rational selects Q (oriented chains) rather than Z2.
  int openSurface(int points_item, int boundary_item = -1, bool rational = true)
  {
    Lex_request r;
    r.closed = false;
    r.points_item = points_item;
    r.boundary_item = boundary_item;
    r.rational = rational;
    return run(r, false);
  }

  // the reason why the last run made no item ("" after a success)
  QString lastError() const { return last_error; }

  // for the tests of cancellation: scripted runs press Cancel when the progress reaches
  // `progress` (negative: never, the default)
  void setCancelAt(double progress) { cancel_at = progress; }

  QString meshStatistics(int item) const;
  bool saveSnapshot(const QString& file);

private:
  void run_from_dialog(bool closed);
  int run(const Lex_request& r, bool interactive);
  QString reconstruct(const Lex_request& r, const std::vector<Point>& points, Progress& progress, SMesh& mesh) const;
  int fail(const QString& reason, bool interactive);

  QAction* actionClosed = nullptr;
  QAction* actionOpen = nullptr;
  QString last_error;
  double cancel_at = -1;
}; // end Polyhedron_demo_lex_optimal_chains_plugin

// The dialog lists the other selected items that can serve as interior points (point sets) or
// as boundary (polylines); the main selection is the point set to reconstruct.
void Polyhedron_demo_lex_optimal_chains_plugin::run_from_dialog(bool closed)
{
  Lex_request r;
  r.closed = closed;
  r.points_item = scene->mainSelectionIndex();
  Lex_optimal_chains_dialog::Item_list candidates;
  for(const CGAL::Three::Scene_interface::Item_id id : scene->selectionIndices()) {
    CGAL::Three::Scene_item* item = scene->item(id);
    if(id == r.points_item) continue;
    if(closed ? qobject_cast<Scene_points_with_normal_item*>(item) != nullptr
              : qobject_cast<Scene_polylines_item*>(item) != nullptr)
      candidates.append(qMakePair(id, item->name()));
  }
  Lex_optimal_chains_dialog dialog(mw, closed, candidates);
  if(dialog.exec() != QDialog::Accepted) return;
  dialog.fill(r);
  run(r, true);
}

// The library's one-line reason: a message box when a user clicked the action, the message
// panel (and lastError()) only when a script called (a modal box would block the script).
int Polyhedron_demo_lex_optimal_chains_plugin::fail(const QString& reason, bool interactive)
{
  last_error = reason;
  std::cerr << "Lex_optimal_chains: " << reason.toStdString() << std::endl;
  CGAL::Three::Three::error(reason);
  if(interactive) QMessageBox::warning(mw, tr("Lexicographic optimal surface"), reason);
  return -1;
}

// Runs a request. The scene changes only on success: a new surface mesh item is added and
// the point set is hidden; on an error or a cancellation nothing is added or modified.
int Polyhedron_demo_lex_optimal_chains_plugin::run(const Lex_request& r, bool interactive)
{
  last_error.clear();
  const auto* pts_item = qobject_cast<Scene_points_with_normal_item*>(scene->item(r.points_item));
  if(pts_item == nullptr) return fail(tr("the item to reconstruct is not a point set"), interactive);
  if(r.closed && r.interior_item >= 0 &&
     (r.interior_item == r.points_item || !qobject_cast<Scene_points_with_normal_item*>(scene->item(r.interior_item))))
    return fail(tr("the interior points must be another point set item"), interactive);
  if(!r.closed && r.boundary_item >= 0 && !qobject_cast<Scene_polylines_item*>(scene->item(r.boundary_item)))
    return fail(tr("the boundary must be a polylines item"), interactive);
  const std::vector<Point> points = points_of(*pts_item);
  const QString title = r.closed ? tr("Closed surface of %1").arg(pts_item->name())
                                 : tr("Open surface of %1").arg(pts_item->name());

  std::unique_ptr<SMesh> mesh(new SMesh);
  QString summary;
  {
    Progress progress(mw, title, interactive ? -1.0 : cancel_at);
    QApplication::setOverrideCursor(Qt::WaitCursor);
    try {
      summary = reconstruct(r, points, progress, *mesh);
    } catch(const LOC::Input_error& e) {
      QApplication::restoreOverrideCursor();
      if(e.code() != LOC::Input_error_code::CANCELLED) return fail(QString::fromStdString(e.what()), interactive);
      last_error = tr("cancelled");
      CGAL::Three::Three::information(tr("%1: cancelled, the scene is unchanged").arg(title));
      return -1;
    } catch(const std::exception& e) { // not an input error: a bug, reported rather than a crash
      QApplication::restoreOverrideCursor();
      return fail(tr("unexpected error: %1").arg(e.what()), interactive);
    }
    QApplication::restoreOverrideCursor();
  }

  const Mesh_statistics s = mesh_statistics(*mesh);
  Scene_surface_mesh_item* new_item = new Scene_surface_mesh_item(mesh.release());
  new_item->setName(r.closed ? tr("%1 (lexicographic closed surface)").arg(pts_item->name())
                             : tr("%1 (lexicographic open surface)").arg(pts_item->name()));
  new_item->setColor(Qt::lightGray);
  new_item->invalidateOpenGLBuffers();
  const CGAL::Three::Scene_interface::Item_id id = scene->addItem(new_item);
  scene->item(r.points_item)->setVisible(false);
  scene->itemChanged(r.points_item);
  CGAL::Three::Three::information(tr("%1: %2 faces, %3 vertices, %4 component(s), genus %5, %6; %7")
                                    .arg(title).arg(s.faces).arg(s.vertices).arg(s.components).arg(s.genus)
                                    .arg(s.closed ? tr("closed") : tr("%1 border edges").arg(s.border_edges))
                                    .arg(summary));
  return id;
}

// Calls the library; returns the statistics of its report that the mesh does not tell
// (timings, non-manifold splits). Throws the library's Input_error.
QString Polyhedron_demo_lex_optimal_chains_plugin::reconstruct(const Lex_request& r, const std::vector<Point>& points,
                                                               Progress& progress, SMesh& mesh) const
{
  const unsigned threads = unsigned(std::max(1, QThread::idealThreadCount()));
  if(r.closed) {
    std::vector<Point> interior;
    if(r.interior_item >= 0)
      interior = points_of(*qobject_cast<Scene_points_with_normal_item*>(scene->item(r.interior_item)));
    const auto np = LOC::parameters::interior_points(interior,
                    LOC::parameters::robust(r.robust,
                    LOC::parameters::keep_non_manifold(r.keep_non_manifold,
                    LOC::parameters::number_of_threads(threads,
                    LOC::parameters::callback(progress.callback())))));
    // a fixed threshold only when one is given, as lex_reconstruct --min-persistence
    const LOC::Closed_surface_report report =
      r.min_persistence > 0
        ? CGAL::lex_optimal_closed_surface_reconstruction(points, mesh, LOC::parameters::minimum_interior_persistence(r.min_persistence, np))
        : CGAL::lex_optimal_closed_surface_reconstruction(points, mesh, np);
    QString smoothing;
    if(report.robust)
      smoothing = tr("; smoothed: k %1, %2 passes, noise estimate %3 (spacing %4)")
                    .arg(report.smoothing_neighbors).arg(report.smoothing_passes)
                    .arg(report.noise_estimate).arg(report.average_spacing);
    return tr("%1 interior (persistence %2, next void %3)%4; %5 non-manifold edges, %6 non-manifold vertices split; "
              "times: Delaunay %7 s, order %8 s, cut %9 s, resolution %10 s, mesh %11 s, total %12 s")
      .arg(report.automatic_interior ? tr("automatic") : tr("given")).arg(report.interior_persistence)
      .arg(report.runner_up_persistence).arg(smoothing)
      .arg(report.non_manifold_edges).arg(report.non_manifold_vertices)
      .arg(report.delaunay_seconds).arg(report.order_seconds).arg(report.cut_seconds)
      .arg(report.resolution_seconds).arg(report.output_seconds).arg(report.total_seconds);
  }
  // as lex_reconstruct --auto-boundary: the skirt joining the footprint polygon to the
  // points is not part of the terrain
  std::vector<std::vector<Point>> boundary;
  if(r.boundary_item < 0)
    boundary.push_back(LOC::footprint_boundary(points));
  else
    for(const auto& polyline : qobject_cast<Scene_polylines_item*>(scene->item(r.boundary_item))->polylines)
      boundary.emplace_back(polyline.begin(), polyline.end());
  const LOC::Open_surface_report report = CGAL::lex_optimal_open_surface_reconstruction(
    points, boundary, mesh,
    LOC::parameters::coefficient_field(r.rational ? LOC::Coefficient_field::Q : LOC::Coefficient_field::Z2,
    LOC::parameters::remove_blocking_points(r.remove_blocking,
    LOC::parameters::drop_boundary_triangles(r.boundary_item < 0,
    LOC::parameters::keep_non_manifold(r.keep_non_manifold,
    LOC::parameters::number_of_threads(threads,
    LOC::parameters::callback(progress.callback())))))));
  QString summary = tr("over %1; %2 boundary triangles dropped, %3 points removed, %4 non-manifold edges split, "
                       "%5 orientation cuts; times: Delaunay %6 s, representative %7 s, order %8 s, "
                       "optimal chain %9 s, resolution %10 s, mesh %11 s, total %12 s")
    .arg(r.rational ? "Q" : "Z2").arg(report.dropped_triangles).arg(report.number_of_removed_points)
    .arg(report.non_manifold_edges).arg(report.orientation_cuts)
    .arg(report.delaunay_seconds).arg(report.representative_seconds).arg(report.order_seconds)
    .arg(report.optimal_chain_seconds).arg(report.resolution_seconds).arg(report.output_seconds)
    .arg(report.total_seconds);
  if(report.number_of_multiple_facets > 0)
    summary += tr("; %1 triangles have a coefficient other than 1 or -1 (the boundary winds more than once "
                  "around them: Z2 ignores the orientations)").arg(report.number_of_multiple_facets);
  return summary;
}

// Scripting: the topology of a surface mesh item as one JSON line, with the keys of
// `lex_reconstruct --json` ("" if the item is not a surface mesh).
QString Polyhedron_demo_lex_optimal_chains_plugin::meshStatistics(int item) const
{
  const auto* sm_item = qobject_cast<Scene_surface_mesh_item*>(scene->item(item));
  if(sm_item == nullptr) return QString();
  const Mesh_statistics s = mesh_statistics(*sm_item->face_graph());
  QJsonObject j;
  j["vertices"] = qint64(s.vertices);
  j["faces"] = qint64(s.faces);
  j["components"] = qint64(s.components);
  j["boundary_edges"] = qint64(s.border_edges);
  j["boundary_loops"] = qint64(s.border_loops);
  j["genus"] = qint64(s.genus);
  j["closed"] = s.closed;
  j["is_closed"] = CGAL::is_closed(*sm_item->face_graph()); // CGAL's own test, as a cross-check
  return QString::fromUtf8(QJsonDocument(j).toJson(QJsonDocument::Compact));
}

// Scripting: writes the main 3D view to an image file (see demo/common/View_snapshot.h).
bool Polyhedron_demo_lex_optimal_chains_plugin::saveSnapshot(const QString& file)
{
  if(save_view_snapshot(file, last_error)) return true;
  std::cerr << "Lex_optimal_chains: " << last_error.toStdString() << std::endl;
  return false;
}

#include "Lex_optimal_chains_plugin.moc"
