// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file MeshFileChecks.h
 * @brief The checks a mesh file passes before a VTK 9.2 reader sees it, one function per format.
 *
 * VTK's readers trust their files. On damaged ones, found by fuzzing meshsimplify with a few
 * thousand files: vtkPLYReader reads on after a header without x y z (freed memory, SIGSEGV), past
 * the words of a short ASCII line, and through face indices into missing points;
 * vtkOBJReader follows texture and normal indices that do not exist and copies material names
 * into a 100-byte buffer; vtkSTLReader, vtkPolyDataReader and vtkXMLPolyDataReader allocate
 * whatever a count or a block header declares (2^31 points: abort), and the XML reader
 * crashes on negative counts. Each check below therefore walks as much of the file as the
 * reader trusts: the PLY header and every record up to the faces, every face corner of an OBJ
 * file, the size of a binary STL, every count of a legacy VTK file against the file's size,
 * and every array of a VTK XML file against the data its block headers describe.
 *
 * Each function returns "" when the reader may be given the file, else the reason, one line.
 * They take files that passed the common checks (an existing, readable, non-empty regular
 * file). Our OFF reader checks its files itself and needs none.
 *
 * Each format's checks live in a file of their own: CheckPLY.cxx, CheckSTL.cxx, CheckOBJ.cxx,
 * CheckVTP.cxx (with XmlMarkupScan.h's markup pass) and CheckLegacyVTK.cxx; the helpers they
 * share (file size, words, numbers, quoting) in MeshFileCheckText.h.
 */
#ifndef MeshSimplification_MeshFileChecks_h
#define MeshSimplification_MeshFileChecks_h

#include <string>

namespace meshfiles
{

/// ASCII and binary PLY: the header (a format line, element vertex with scalar x y z first,
/// element face with a vertex_indices list of integers second, known types, end_header), then
/// every vertex and face record: present, numbers where numbers belong, list lengths within
/// their type and at most 255 corners, corner indices naming existing vertices; ASCII and double
/// coordinates within float's normal range (the reader stores floats: 1e300 would become
/// infinite, a mesh of 1e-300 collapse to 0; float ones are stored as they are); without further elements, nothing after the declared faces (the
/// reader would drop faces a short count leaves out).
std::string CheckPLY(const std::string& path);

/// STL, as VTK tells binary from ASCII: a binary file is 84 bytes plus 50 per triangle of its
/// count; an ASCII one starts with "solid" and has facet and vertex lines.
std::string CheckSTL(const std::string& path);

/// OBJ: text without NUL bytes, lines and material names within vtkOBJReader's buffers, finite
/// vertex coordinates (the reader reads nan and inf as other numbers), and every face corner
/// (parsed as the reader parses it) naming an existing vertex, texture coordinate and normal.
std::string CheckOBJ(const std::string& path);

/// VTK XML polydata (.vtp): markup within XmlMarkupScan.h's limits, structure read by VTK's XML
/// parser, then every array of every piece: known type, format and compressor, a block header
/// whose sizes fit the bytes that follow, and as many values as the piece's counts (or the last
/// cell offset) make the reader expect, and no more offsets than cells (the reader would drop the
/// cells a short count leaves out).
/// The last offset is only read from uncompressed arrays (zlib's checksum guards the rest).
std::string CheckVTP(const std::string& path);

/// Legacy VTK polydata (.vtk): the header lines, and every count of a section line (POINTS,
/// POLYGONS, POINT_DATA, SCALARS, FIELD arrays, ...) non-negative and small enough for its
/// values to fit in the file.
std::string CheckLegacyVTK(const std::string& path);

} // namespace meshfiles

#endif
