// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file XmlMarkupScan.h
 * @brief One bounded pass over an XML file's markup, before any XML parser sees it.
 *
 * Two shapes of a small file make VTK 9.2's XML reading fail without a word, whatever else the
 * file holds:
 *   - deep nesting: vtkXMLDataElement frees its nested elements recursively, so about 20 000
 *     nested elements (a 140 KB file) overflow the stack (SIGSEGV), in vtkXMLPolyDataReader as
 *     in any check that parses with vtkXMLDataParser;
 *   - one long markup token (a start tag with a long attribute value, a comment, a processing
 *     instruction): Debian 12's expat (2.5) parses it again for every block VTK feeds it, so
 *     its time grows with the square of its length (2 MiB: 0.6 s, 20 MiB: 55 s). Character
 *     data, which expat hands on in pieces, costs linear time.
 * VTK files nest about 6 elements deep and have attribute values of a few dozen characters, so
 * the limits below refuse no file VTK writes, and hold a refused file's parse to milliseconds.
 * The pass reads each byte once, with no recursion, and stops where appended data begins
 * (VTK's parser stops there too). Document type declarations, which VTK files never have, are
 * refused with it: they are where entity expansion hides.
 */
#ifndef MeshSimplification_XmlMarkupScan_h
#define MeshSimplification_XmlMarkupScan_h

#include <cstddef>
#include <string>

namespace meshfiles
{

/// Deepest element nesting accepted.
constexpr int MaximumXmlDepth = 256;
/// Longest markup token accepted, '<' to '>', in bytes.
constexpr std::size_t MaximumXmlToken = 64 * 1024;

/// "" when the file's markup is within the limits, else the first breach, one line (with its
/// byte offset). A file that ends inside a token is left to the parser to report.
std::string ScanXmlMarkup(const std::string& path);

} // namespace meshfiles

#endif
