// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_ERROR_CODE_H
#define CGAL_QD_ERROR_CODE_H

/// \file Error_code.h
/// Status codes returned by every CGAL_QD algorithm.

#include <ostream>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// status of a CGAL_QD algorithm. On any value other than `OK`, the algorithm
/// has written nothing to the caller's property maps.
enum class Error_code {
  OK,                      ///< success
  EMPTY_MESH,              ///< the mesh (or patch) has no face
  NOT_TRIANGLE_MESH,       ///< a face is not a triangle
  NON_MANIFOLD,            ///< a vertex is non-manifold (several umbrellas meet at it)
  NOT_CONNECTED,           ///< the patch has several connected components
  NO_BORDER,               ///< the patch is closed: it has no border loop
  NOT_A_DISK,              ///< the patch is not a disk with holes (its genus is positive)
  INVALID_BORDER_HALFEDGE, ///< the `border` halfedge is null or not a border halfedge of the patch
  INVALID_COORDINATES,     ///< a vertex has a NaN or infinite coordinate
  DEGENERATE_EDGE,         ///< a border edge has zero length
  DEGENERATE_FACE,         ///< a face has zero area (collinear or coincident corners)
  SOLVER_FAILED,           ///< a numerical solve failed or produced non-finite values
  NOT_CONVERGED,           ///< the iteration limit was reached before the tolerance
  CANNOT_OPEN_FILE,        ///< the file does not exist or cannot be read
  INVALID_FILE,            ///< the file is empty, of an unknown format, truncated or malformed
  INVALID_INDEX,           ///< a polygon refers to a point that does not exist
  INVALID_ARGUMENT,        ///< an argument does not fit: an output that is not empty, a result of another mesh
  CANNOT_WRITE,            ///< the output stream failed, or the library that writes the file did
  /// the largest |coordinate| is outside [2^-64, 2^64] (about 5e-20 to 1.8e19), where squared
  /// areas overflow or underflow; `segment_quasi_developable()` and `flatten_patch()` scale such
  /// meshes internally instead
  COORDINATES_OUT_OF_RANGE
};

/// \ingroup PkgCGAL_QDRef
/// returns a sentence that says what `code` means, for messages to users.
inline const char* error_message(Error_code code)
{
  switch(code) {
    case Error_code::OK: return "success";
    case Error_code::EMPTY_MESH: return "the mesh has no face";
    case Error_code::NOT_TRIANGLE_MESH: return "the mesh has a face that is not a triangle";
    case Error_code::NON_MANIFOLD: return "the mesh has a non-manifold vertex";
    case Error_code::NOT_CONNECTED: return "the patch has several connected components";
    case Error_code::NO_BORDER: return "the patch is closed (it has no border); cut it open first";
    case Error_code::NOT_A_DISK:
      return "the patch is not a topological disk with holes (its genus is positive)";
    case Error_code::INVALID_BORDER_HALFEDGE:
      return "the given halfedge is not a border halfedge of the patch";
    case Error_code::INVALID_COORDINATES: return "a vertex has a NaN or infinite coordinate";
    case Error_code::DEGENERATE_EDGE: return "a border edge has zero length";
    case Error_code::DEGENERATE_FACE: return "the mesh has a degenerate (zero-area) face";
    case Error_code::SOLVER_FAILED: return "a numerical solve failed";
    case Error_code::NOT_CONVERGED: return "the iteration limit was reached before convergence";
    case Error_code::CANNOT_OPEN_FILE: return "the file does not exist or cannot be opened";
    case Error_code::INVALID_FILE:
      return "the file is not a valid mesh file (empty, unknown format, truncated, wrong counts or unreadable numbers)";
    case Error_code::INVALID_INDEX: return "a polygon refers to a point that does not exist";
    case Error_code::INVALID_ARGUMENT:
      return "an argument does not fit (an output mesh that is not empty, or a result that belongs to another mesh)";
    case Error_code::CANNOT_WRITE: return "the output could not be written";
    case Error_code::COORDINATES_OUT_OF_RANGE:
      return "the coordinates are out of range (the largest is beyond 2^64 or below 2^-64); scale the mesh";
  }
  return "unknown error code";
}

/// \ingroup PkgCGAL_QDRef
/// writes `error_message(code)`.
inline std::ostream& operator<<(std::ostream& out, Error_code code) { return out << error_message(code); }

} // namespace CGAL_QD

#endif // CGAL_QD_ERROR_CODE_H
