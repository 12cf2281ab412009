// The Lex_optimal_chains plugin of CGAL's Polyhedron demo: surface reconstruction of a point
// set item as a lexicographic optimal chain of its Delaunay triangulation.
//
// Three actions on a point set item:
//  - "Closed surface (lexicographic)": the interior is found automatically (the most persistent
//    void), or given by the points of another selected point set item;
//  - "Open surface (lexicographic)": the surface bounded by the closed polylines of a selected
//    polylines item, or by the automatic footprint polygon (terrain tiles), over Q or Z2;
//  - "Feature-guided reconstruction (lexicographic)": the elements of the critical basis
//    around sharp features (lex_optimal_feature_reconstruction()), one colour per element.
// The result is a new surface mesh item; the statistics of the report go to the message panel.
// For the first two, a progress dialog shows the stages and can cancel (the scene is then left
// unchanged).
//
// Scripting (the demo's QtScript, as in the headless tests): the plugin object is the global
// `lex_optimal_chains_plugin`; its slots closedSurface(), openSurface(),
// featureReconstruction(), lastError(), meshStatistics(), saveSnapshot() and setCancelAt() run
// everything without a modal dialog: errors go to the message panel and to lastError()
// instead of a message box.

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFormLayout>
#include <QFileInfo>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMainWindow>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSpinBox>
#include <QThread>

#include "Scene_points_with_normal_item.h"
#include "Scene_polylines_item.h"
#include "Scene_surface_mesh_item.h"
#include "SMesh_type.h"

#include <CGAL/Three/Three.h>
#include <CGAL/Three/Viewer_interface.h>

#include <CGAL/lex_optimal_closed_surface.h>
#include <CGAL/lex_optimal_feature_reconstruction.h>
#include <CGAL/lex_optimal_open_surface.h>
#include <CGAL/Lex_optimal_chains/Cancelled.h>
#include <CGAL/Lex_optimal_chains/footprint_boundary.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/property_map.h>
#include <CGAL/Random.h>

#include "ui_Lex_optimal_chains_dialog.h"
// the interface of the demo built for, included here for moc, which reads the plugin's own
// includes only (see Demo_compatibility.h)
#ifdef URBAN_DEMO_CGAL_LAB
#include <CGAL/Three/CGAL_Lab_plugin_interface.h>
#else
#include <CGAL/Three/Polyhedron_demo_plugin_interface.h>
#endif
#include "Demo_compatibility.h"
#include "View_snapshot.h"

#include <functional>
#include <iostream>
#include <memory>
#include <set>
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
// library throws Lex_optimal_chains::Cancelled before it modifies the output mesh. `cancel_at`
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

// The parameters of the feature-guided reconstruction (lex_reconstruct features).
struct Feature_request
{
  CGAL::Three::Scene_interface::Item_id points_item = -1;
  double threshold = 0.16; // of the VCM
  double offset = 0;       // of the feature set; 0 for the library's default
  int drop_largest = 0;
  bool borders = false, relative = false;
};

// The dialog of the feature-guided reconstruction (built in code: five fields).
class Feature_dialog : public QDialog
{
public:
  explicit Feature_dialog(QWidget* parent) : QDialog(parent)
  {
    setWindowTitle(tr("Feature-guided reconstruction (lexicographic)"));
    auto* form = new QFormLayout(this);
    threshold_->setRange(0.01, 0.5);
    threshold_->setSingleStep(0.01);
    threshold_->setValue(0.16);
    form->addRow(tr("VCM threshold"), threshold_);
    offset_->setRange(0, 1e9);
    offset_->setDecimals(4);
    offset_->setSpecialValueText(tr("1.5 x average spacing"));
    form->addRow(tr("Feature offset"), offset_);
    drop_->setRange(0, 1000);
    form->addRow(tr("Largest elements left out"), drop_);
    borders_->setText(tr("Borders of the scan as features (opens occlusion holes)"));
    form->addRow(borders_);
    relative_->setText(tr("Chains relative to the features"));
    form->addRow(relative_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
  }

  void fill(Feature_request& r) const
  {
    r.threshold = threshold_->value();
    r.offset = offset_->value();
    r.drop_largest = drop_->value();
    r.borders = borders_->isChecked();
    r.relative = relative_->isChecked();
  }

private:
  QDoubleSpinBox* threshold_ = new QDoubleSpinBox(this);
  QDoubleSpinBox* offset_ = new QDoubleSpinBox(this);
  QSpinBox* drop_ = new QSpinBox(this);
  QCheckBox* borders_ = new QCheckBox(this);
  QCheckBox* relative_ = new QCheckBox(this);
};

class Polyhedron_demo_lex_optimal_chains_plugin : public QObject, public Urban_demo::Plugin_helper
{
  Q_OBJECT
#ifdef URBAN_DEMO_CGAL_LAB // see Demo_compatibility.h
  Q_INTERFACES(CGAL::Three::CGAL_Lab_plugin_interface)
  Q_PLUGIN_METADATA(IID "com.geometryfactory.CGALLab.PluginInterface/1.0")
#else
  Q_INTERFACES(CGAL::Three::Polyhedron_demo_plugin_interface)
  Q_PLUGIN_METADATA(IID "com.geometryfactory.PolyhedronDemo.PluginInterface/1.0")
#endif

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
    actionFeatures = new QAction(tr("Feature-guided reconstruction (lexicographic)"), mw);
    actionFeatures->setObjectName("actionLexFeatures");
    actionFeatures->setProperty("subMenuName", "Point Set Processing/Surface Reconstruction");
    autoConnectActions();
  }

  bool applicable(QAction*) const override
  {
    return qobject_cast<Scene_points_with_normal_item*>(scene->item(scene->mainSelectionIndex())) != nullptr;
  }

  QList<QAction*> actions() const override { return QList<QAction*>() << actionClosed << actionOpen << actionFeatures; }

public Q_SLOTS:
  void on_actionLexClosedSurface_triggered() { run_from_dialog(true); }
  void on_actionLexOpenSurface_triggered() { run_from_dialog(false); }
  void on_actionLexFeatures_triggered()
  {
    Feature_request r;
    r.points_item = scene->mainSelectionIndex();
    Feature_dialog dialog(mw);
    if(dialog.exec() != QDialog::Accepted) return;
    dialog.fill(r);
    run_features(r, true);
  }

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

  // Scripting: the feature-guided reconstruction (lex_reconstruct features); offset 0 for the
  // library's default. The faces of the new item carry their element as their patch id.
  int featureReconstruction(int points_item, double threshold = 0.16, double offset = 0, int drop_largest = 0,
                            bool borders = false, bool relative = false)
  {
    Feature_request r;
    r.points_item = points_item;
    r.threshold = threshold;
    r.offset = offset;
    r.drop_largest = drop_largest;
    r.borders = borders;
    r.relative = relative;
    return run_features(r, false);
  }

  // the reason why the last run made no item ("" after a success)
  QString lastError() const { return last_error; }

  // for the tests of cancellation: scripted runs press Cancel when the progress reaches
  // `progress` (negative: never, the default)
  void setCancelAt(double progress) { cancel_at = progress; }

  QString meshStatistics(int item) const;
  bool saveSnapshot(const QString& file);
  // whether an item is shown (a script must not hold `scene.item(i)`: CGAL Lab's script engine
  // takes the item and deletes it when the demo quits)
  bool itemVisible(int item) const { return scene->item(item) && scene->item(item)->visible(); }

private:
  void run_from_dialog(bool closed);
  int run(const Lex_request& r, bool interactive);
  QString reconstruct(const Lex_request& r, const std::vector<Point>& points, Progress& progress, SMesh& mesh) const;
  int fail(const QString& reason, bool interactive);
  int run_features(const Feature_request& r, bool interactive);

  QAction* actionClosed = nullptr;
  QAction* actionOpen = nullptr;
  QAction* actionFeatures = nullptr;
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
    } catch(const LOC::Cancelled&) {
      QApplication::restoreOverrideCursor();
      last_error = tr("cancelled");
      CGAL::Three::Three::information(tr("%1: cancelled, the scene is unchanged").arg(title));
      return -1;
    } catch(const LOC::Input_error& e) {
      QApplication::restoreOverrideCursor();
      return fail(QString::fromStdString(e.what()), interactive);
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

// Runs the feature-guided reconstruction: on success a new surface mesh item, one colour per
// element (its patch id), the point set hidden; on an error nothing is added or modified.
int Polyhedron_demo_lex_optimal_chains_plugin::run_features(const Feature_request& r, bool interactive)
{
  last_error.clear();
  const auto* pts_item = qobject_cast<Scene_points_with_normal_item*>(scene->item(r.points_item));
  if(pts_item == nullptr) return fail(tr("the item to reconstruct is not a point set"), interactive);
  if(r.drop_largest < 0) return fail(tr("the number of elements left out must not be negative"), interactive);
  const std::vector<Point> points = points_of(*pts_item);
  std::unique_ptr<SMesh> mesh(new SMesh);
  auto element = mesh->add_property_map<SMesh::Face_index, std::size_t>("f:lex_element", 0).first; // moved to the item's patch ids
  LOC::Feature_reconstruction_report report;
  QApplication::setOverrideCursor(Qt::WaitCursor);
  try {
    const auto np = LOC::parameters::feature_threshold(r.threshold,
                    LOC::parameters::border_features(r.borders,
                    LOC::parameters::relative_to_features(r.relative,
                    LOC::parameters::drop_largest_elements(std::size_t(r.drop_largest),
                    LOC::parameters::face_element_map(element)))));
    report = r.offset > 0 ? CGAL::lex_optimal_feature_reconstruction(points, *mesh, LOC::parameters::feature_offset(r.offset, np))
                          : CGAL::lex_optimal_feature_reconstruction(points, *mesh, np);
  } catch(const LOC::Input_error& e) {
    QApplication::restoreOverrideCursor();
    return fail(QString::fromStdString(e.what()), interactive);
  } catch(const std::exception& e) {
    QApplication::restoreOverrideCursor();
    return fail(tr("unexpected error: %1").arg(e.what()), interactive);
  }
  QApplication::restoreOverrideCursor();
  const Mesh_statistics s = mesh_statistics(*mesh);
  // as the demo's shape detection colours its regions: the item first, then the patch ids (the
  // element of each face) and one colour per element
  Scene_surface_mesh_item* new_item = new Scene_surface_mesh_item;
  new_item->setName(tr("%1 (lexicographic elements)").arg(pts_item->name()));
  SMesh& fg = *new_item->polyhedron();
  fg = *mesh;
  auto fg_element = *Urban_demo::found_property_map(fg.property_map<SMesh::Face_index, std::size_t>("f:lex_element"));
  auto patch = fg.add_property_map<SMesh::Face_index, int>("f:patch_id", 0).first;
  for(SMesh::Face_index f : fg.faces()) patch[f] = int(fg_element[f]);
  fg.remove_property_map(fg_element);
  new_item->setItemIsMulticolor(true);
  new_item->computeItemColorVectorAutomatically(false);
  auto& colors = new_item->color_vector();
  colors.clear();
  for(std::size_t e = 0; e < report.element_sizes.size(); ++e) {
    CGAL::Random random(static_cast<unsigned int>(e));
    colors.push_back(QColor(64 + random.get_int(0, 192), 64 + random.get_int(0, 192), 64 + random.get_int(0, 192)));
  }
  new_item->invalidateOpenGLBuffers();
  const CGAL::Three::Scene_interface::Item_id id = scene->addItem(new_item);
  scene->item(r.points_item)->setVisible(false);
  scene->itemChanged(r.points_item);
  CGAL::Three::Three::information(
    tr("Elements of %1: %2 feature points (%3 on borders), beta %4, %5 elements (%6 left out), %7 faces, "
       "%8 vertices, %9 component(s); times: Delaunay %10 s, features %11 s, subcomplex %12 s, chains %13 s, "
       "basis %14 s, total %15 s")
      .arg(pts_item->name()).arg(report.number_of_feature_points).arg(report.number_of_border_points)
      .arg(report.number_of_cycles).arg(report.element_sizes.size()).arg(report.number_of_dropped_elements)
      .arg(s.faces).arg(s.vertices).arg(s.components).arg(report.delaunay_seconds).arg(report.feature_seconds)
      .arg(report.subcomplex_seconds).arg(report.chain_seconds).arg(report.basis_seconds).arg(report.total_seconds));
  return id;
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
  const auto patch = Urban_demo::found_property_map(sm_item->face_graph()->property_map<SMesh::Face_index, int>("f:patch_id"));
  if(patch) { // the elements of a feature-guided reconstruction
    std::set<int> elements;
    for(SMesh::Face_index f : sm_item->face_graph()->faces()) elements.insert((*patch)[f]);
    j["elements"] = qint64(elements.size());
  }
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
