// Copyright (c) 2026  The Lex_optimal_chains and Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The screenshot of the demo's 3D view that the plugins' scripts take (headless tests).

#ifndef URBAN_DEMO_VIEW_SNAPSHOT_H
#define URBAN_DEMO_VIEW_SNAPSHOT_H

#include <QApplication>
#include <QImage>
#include <QObject>
#include <QString>

#include <CGAL/Three/Three.h>
#include <CGAL/Three/Viewer_interface.h>

// Writes the main 3D view to an image file (PNG by extension) and returns true, or returns
// false with the reason in `error`. A script runs before the demo's event loop starts, so the
// events are processed first: the window gets exposed, its OpenGL context initialized and the
// new items' buffers computed. An image of a single colour (nothing drawn: no working OpenGL)
// is refused.
inline bool save_view_snapshot(const QString& file, QString& error)
{
  CGAL::Three::Viewer_interface* viewer = CGAL::Three::Three::mainViewer();
  for(int i = 0; i < 10; ++i) QApplication::processEvents();
  viewer->showEntireScene();
  const QImage image = viewer->grabFramebuffer();
  bool drawn = false;
  for(int y = 0; y < image.height() && !drawn; ++y)
    for(int x = 0; x < image.width() && !drawn; ++x) drawn = image.pixel(x, y) != image.pixel(0, 0);
  if(!drawn)
    error = QObject::tr("the 3D view is empty (no OpenGL?): no snapshot saved to %1").arg(file);
  else if(!image.save(file))
    error = QObject::tr("cannot save a snapshot to %1").arg(file);
  else
    return true;
  return false;
}

#endif // URBAN_DEMO_VIEW_SNAPSHOT_H
