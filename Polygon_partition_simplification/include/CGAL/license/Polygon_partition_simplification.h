// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The license check of the Polygon Partition Simplification package, as CGAL's own packages do it
// (CGAL/license/<Package>.h): a commercial license is declared by defining
// CGAL_POLYGON_PARTITION_SIMPLIFICATION_COMMERCIAL_LICENSE to its date; CGAL_LICENSE_WARNING and
// CGAL_LICENSE_ERROR make the license in use visible at compile time.

#ifndef CGAL_LICENSE_POLYGON_PARTITION_SIMPLIFICATION_H
#define CGAL_LICENSE_POLYGON_PARTITION_SIMPLIFICATION_H

#include <CGAL/config.h>
#include <CGAL/license.h>

#ifdef CGAL_POLYGON_PARTITION_SIMPLIFICATION_COMMERCIAL_LICENSE

#  if CGAL_POLYGON_PARTITION_SIMPLIFICATION_COMMERCIAL_LICENSE < CGAL_RELEASE_DATE
#    if defined(CGAL_LICENSE_WARNING)
       CGAL_pragma_warning("Your commercial license for CGAL does not cover "
                           "this release of the Polygon Partition Simplification package.")
#    endif
#    ifdef CGAL_LICENSE_ERROR
#      error "Your commercial license for CGAL does not cover this release \
              of the Polygon Partition Simplification package. \
              You get this error, as you defined CGAL_LICENSE_ERROR."
#    endif
#  endif

#else // no CGAL_POLYGON_PARTITION_SIMPLIFICATION_COMMERCIAL_LICENSE

#  if defined(CGAL_LICENSE_WARNING)
     CGAL_pragma_warning("\nThe macro CGAL_POLYGON_PARTITION_SIMPLIFICATION_COMMERCIAL_LICENSE is not defined."
                         "\nYou use the Polygon Partition Simplification package under the terms of the GPLv3+.")
#  endif
#  ifdef CGAL_LICENSE_ERROR
#    error "The macro CGAL_POLYGON_PARTITION_SIMPLIFICATION_COMMERCIAL_LICENSE is not defined. \
            You use the Polygon Partition Simplification package under the terms of the GPLv3+. \
            You get this error, as you defined CGAL_LICENSE_ERROR."
#  endif

#endif // no CGAL_POLYGON_PARTITION_SIMPLIFICATION_COMMERCIAL_LICENSE

#endif // CGAL_LICENSE_POLYGON_PARTITION_SIMPLIFICATION_H
