// SPDX-License-Identifier: BSD-3-Clause
// meshsimplify on damaged mesh files of every format, written here at test time: each run must
// exit with status 1 and one line "meshsimplify: cannot read '<file>': <reason>", never by a
// signal, within 10 s. The same tetrahedron, undamaged, must be read in every format (the
// checks refuse no sound file). Before the checks, the PLY files without faces and z, truncated
// or with a short line, the OBJ naming missing texture coordinates, the STL, VTP and VTK
// declaring 2^31 - 1 entries, field arrays of no or an unknown type in VTP and VTK, and a VTP
// nested 20 000 deep crashed it; a VTP with a 2 MiB attribute took 0.6 s (20 MiB: 55 s); NaN
// in OBJ, short face counts, PLY doubles beyond float's range and files without a triangle
// gave a wrong mesh or an empty one with exit 0; most others gave no reason or pages of VTK
// messages.
//
//   TestMeshSimplifyBadFiles <meshsimplify> <work directory>
#include <sys/stat.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace
{
int failures = 0;

void Fail(const std::string& message)
{
  std::fprintf(stderr, "check failed: %s\n", message.c_str());
  ++failures;
}

struct Case
{
  std::string Name; // file name; its extension picks the reader
  std::string Bytes;
};

// ------------------------------------------------------------------- the tetrahedron, sound
const float Points[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
const int Faces[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };

template <typename T>
std::string Bytes(T value, bool bigEndian = false)
{
  std::string bytes(sizeof(T), '\0');
  std::memcpy(&bytes[0], &value, sizeof(T));
  if (bigEndian)
  {
    bytes.assign(bytes.rbegin(), bytes.rend());
  }
  return bytes;
}

std::string AsciiPLY()
{
  std::ostringstream ply;
  ply << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
         "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& p : Points)
  {
    ply << p[0] << " " << p[1] << " " << p[2] << "\n";
  }
  for (const auto& f : Faces)
  {
    ply << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
  }
  return ply.str();
}

std::string BinaryPLY(bool bigEndian)
{
  std::string ply = std::string("ply\nformat ") +
    (bigEndian ? "binary_big_endian" : "binary_little_endian") +
    " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& p : Points)
  {
    for (float x : p)
    {
      ply += Bytes(x, bigEndian);
    }
  }
  for (const auto& f : Faces)
  {
    ply += '\3';
    for (int id : f)
    {
      ply += Bytes(static_cast<std::int32_t>(id), bigEndian);
    }
  }
  return ply;
}

/// A binary grid of m x m quads, larger than the checker's 64 KiB read buffer (records straddle
/// its blocks); lastCorner, when not negative, replaces the last face's last corner.
std::string LargeBinaryPLY(int m, std::int32_t lastCorner)
{
  const int n = m + 1;
  std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(n * n) +
    "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(2 * m * m) +
    "\nproperty list uchar int vertex_indices\nend_header\n";
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      for (const float x : { static_cast<float>(i), static_cast<float>(j), static_cast<float>((i * j) % 7) })
      {
        ply += Bytes(x, false);
      }
    }
  }
  for (int j = 0; j < m; ++j)
  {
    for (int i = 0; i < m; ++i)
    {
      const std::int32_t a = j * n + i;
      for (const std::array<std::int32_t, 3>& f : { std::array<std::int32_t, 3>{ a, a + 1, a + n + 1 },
             std::array<std::int32_t, 3>{ a, a + n + 1, a + n } })
      {
        ply += '\3';
        for (int k = 0; k < 3; ++k)
        {
          const bool last = j == m - 1 && i == m - 1 && f[0] == a && f[2] == a + n && k == 2;
          ply += Bytes(last && lastCorner >= 0 ? lastCorner : f[k], false);
        }
      }
    }
  }
  return ply;
}

std::string BinarySTL(std::uint32_t count)
{
  std::string stl(80, ' ');
  stl += Bytes(count);
  for (const auto& f : Faces)
  {
    stl += std::string(12, '\0'); // the normal
    for (int id : f)
    {
      for (float x : Points[id])
      {
        stl += Bytes(x);
      }
    }
    stl += std::string(2, '\0');
  }
  return stl;
}

std::string AsciiSTL()
{
  std::ostringstream stl;
  stl << "solid tetrahedron\n";
  for (const auto& f : Faces)
  {
    stl << " facet normal 0 0 0\n  outer loop\n";
    for (int id : f)
    {
      stl << "   vertex " << Points[id][0] << " " << Points[id][1] << " " << Points[id][2] << "\n";
    }
    stl << "  endloop\n endfacet\n";
  }
  stl << "endsolid tetrahedron\n";
  return stl.str();
}

std::string OBJ()
{
  std::ostringstream obj;
  for (const auto& p : Points)
  {
    obj << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
  }
  for (const auto& f : Faces)
  {
    obj << "f " << f[0] + 1 << " " << f[1] + 1 << " " << f[2] + 1 << "\n";
  }
  return obj.str();
}

std::string OFF()
{
  std::ostringstream off;
  off << "OFF\n4 4 0\n";
  for (const auto& p : Points)
  {
    off << p[0] << " " << p[1] << " " << p[2] << "\n";
  }
  for (const auto& f : Faces)
  {
    off << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
  }
  return off.str();
}

std::string VTP(const std::string& numberOfPoints = "4")
{
  return "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <PolyData>\n"
         "    <Piece NumberOfPoints=\"" +
    numberOfPoints +
    "\" NumberOfPolys=\"4\">\n"
    "      <Points>\n"
    "        <DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">\n"
    "          0 0 0 1 0 0 0 1 0 0 0 1\n"
    "        </DataArray>\n"
    "      </Points>\n"
    "      <Polys>\n"
    "        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n"
    "          0 2 1 0 1 3 0 3 2 1 2 3\n"
    "        </DataArray>\n"
    "        <DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n"
    "          3 6 9 12\n"
    "        </DataArray>\n"
    "      </Polys>\n"
    "    </Piece>\n"
    "  </PolyData>\n"
    "</VTKFile>\n";
}

std::string LegacyVTK(const std::string& numberOfPoints = "4")
{
  return "# vtk DataFile Version 3.0\ntetrahedron\nASCII\nDATASET POLYDATA\nPOINTS " +
    numberOfPoints + " float\n0 0 0 1 0 0 0 1 0 0 0 1\nPOLYGONS 4 16\n3 0 2 1\n3 0 1 3\n"
                     "3 0 3 2\n3 1 2 3\n";
}

/// The legacy tetrahedron with a FIELD block before its points.
std::string LegacyVTKWithField(const std::string& field)
{
  const std::string sound = LegacyVTK();
  const std::size_t points = sound.find("POINTS");
  return sound.substr(0, points) + field + sound.substr(points);
}

/// The XML tetrahedron with extra markup after its PolyData element.
std::string VTPWithMarkup(const std::string& markup)
{
  const std::string sound = VTP();
  const std::size_t end = sound.find("</VTKFile>");
  return sound.substr(0, end) + markup + sound.substr(end);
}

/// An ASCII PLY tetrahedron declaring faces faces (4 follow), of doubles scaled by scale.
std::string DoublePLY(int faces, double scale)
{
  std::ostringstream ply;
  ply << "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
         "property double z\nelement face "
      << faces << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& p : Points)
  {
    ply << p[0] * scale << " " << p[1] * scale << " " << p[2] * scale << "\n";
  }
  for (const auto& f : Faces)
  {
    ply << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
  }
  return ply.str();
}

/// The binary PLY tetrahedron with its face count replaced.
std::string BinaryPLYDeclaring(int faces)
{
  std::string ply = BinaryPLY(false);
  return ply.replace(ply.find("element face 4"), 14, "element face " + std::to_string(faces));
}

/// The OBJ tetrahedron with one coordinate replaced by word.
std::string OBJWithCoordinate(const std::string& word)
{
  std::string obj = OBJ();
  return obj.replace(obj.find("v 0 1 0"), 7, "v 0 " + word + " 0");
}

/// Elements nested depth deep.
std::string Nested(int depth)
{
  std::string open, close;
  for (int k = 0; k < depth; ++k)
  {
    open += "<a>";
    close += "</a>";
  }
  return open + close;
}

/// The XML tetrahedron with a FieldData element.
std::string VTPWithField(const std::string& field)
{
  const std::string sound = VTP();
  const std::size_t piece = sound.find("    <Piece");
  return sound.substr(0, piece) + "    <FieldData>\n" + field + "    </FieldData>\n" +
    sound.substr(piece);
}

std::vector<Case> SoundFiles()
{
  return { { "sound_ascii.ply", AsciiPLY() }, { "sound_le.ply", BinaryPLY(false) },
    { "sound_be.ply", BinaryPLY(true) }, { "sound_large.ply", LargeBinaryPLY(60, -1) },
    { "sound_binary.stl", BinarySTL(4) },
    { "sound_ascii.stl", AsciiSTL() }, { "sound.obj", OBJ() }, { "sound.off", OFF() },
    { "sound.vtp", VTP() }, { "sound.vtk", LegacyVTK() },
    { "sound_field.vtk",
      LegacyVTKWithField("FIELD FieldData 2\nuv 2 2 double\n1 2\n3 4\nMETADATA\n"
                         "COMPONENT_NAMES\nu\nv\n\nn 1 1 int\n5\n") },
    { "sound_field_named_lines.vtk",
      LegacyVTKWithField("FIELD FieldData 1\nlines 1 3 int\n1 2 3\n") },
    { "sound_field.vtp",
      VTPWithField("      <DataArray type=\"Float64\" Name=\"x\" NumberOfTuples=\"1\" "
                   "format=\"ascii\">1</DataArray>\n") },
    { "sound_doubles.ply", DoublePLY(4, 1e-30) }, { "sound_blank_lines.ply", AsciiPLY() + "\n \n" },
    { "sound_nested_and_comment.vtp",
      VTPWithMarkup("<!-- " + std::string(1000, 'c') + " -->" + Nested(200)) },
    { "sound_with_a_line.off", OFF().replace(4, 5, "4 5 0") + "2 0 1\n" } };
}

// ------------------------------------------------------------------------- damaged copies
/// Bytes that no reader can make sense of (a fixed pseudo-random sequence).
std::string Garbage(std::size_t size)
{
  std::string bytes(size, '\0');
  std::uint32_t state = 12345;
  for (char& c : bytes)
  {
    state = state * 1664525u + 1013904223u;
    c = static_cast<char>(state >> 24);
  }
  return bytes;
}

std::vector<Case> DamagedFiles()
{
  const std::string ply = AsciiPLY();
  const std::string binary = BinaryPLY(false);
  const std::string stl = BinarySTL(4);
  const std::string vtp = VTP();
  return {
    // The crash of issue 25: vertices with x and y only, and no face element.
    { "no_faces_no_z.ply",
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "end_header\n0 0\n1 0\n0 1\n0 0\n" },
    { "no_faces_no_z_binary.ply",
      "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\n"
      "property float y\nend_header\n" +
        std::string(16, '\0') },
    { "truncated_in_faces.ply", binary.substr(0, binary.size() - 7) },
    { "large_face_index_beyond.ply", LargeBinaryPLY(60, 61 * 61) },
    { "header_ends_the_file.ply", binary.substr(0, binary.find("end_header") + 10) },
    { "large_truncated.ply", LargeBinaryPLY(60, -1).substr(0, 100000) },
    { "truncated_in_vertices.ply", binary.substr(0, binary.find("end_header") + 20) },
    { "face_index_beyond.ply", ply.substr(0, ply.rfind("3 1 2 3")) + "3 1 2 9\n" },
    { "short_vertex_line.ply", ply.substr(0, ply.find("end_header\n") + 11) + "0 0\n" },
    { "truncated.stl", stl.substr(0, 150) },
    { "wrong_count.stl", BinarySTL(5) },
    { "count_2g.stl", BinarySTL(0x7fffffff) },
    { "no_facets.stl", "solid nothing\nendsolid nothing\n" },
    { "wrong_counts.off", "OFF\n4 9 0\n" + OFF().substr(10) },
    { "negative_count.off", "OFF\n-4 4 0\n" },
    { "garbage.obj", Garbage(2000) },
    { "missing_texture_coordinates.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/5/7 2/5/7 3/5/7\n" },
    { "corner_beyond.obj", OBJ() + "f 1 2 99\n" },
    { "garbage.vtp", Garbage(3000) },
    { "truncated.vtp", vtp.substr(0, vtp.size() / 2) },
    { "negative_points.vtp", VTP("-1") },
    { "points_2g.vtp", VTP("2147483647") },
    { "points_2g.vtk", LegacyVTK("2147483647") },
    { "garbage.vtk", Garbage(1000) },
    { "field_type_garbled.vtk", LegacyVTKWithField("FIELD FieldData 1\nx 1 1 d0ouble\n1\n") },
    { "field_type_a_number.vtk", LegacyVTKWithField("FIELD FieldData 1\nx 1 1 8e-12\n") },
    { "offset_beyond_everything.vtp",
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\">\n  <PolyData>\n"
      "    <Piece NumberOfPoints=\"4\" NumberOfPolys=\"1\">\n      <Points>\n"
      "        <DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"appended\" "
      "offset=\"9223372036854775807\"/>\n      </Points>\n    </Piece>\n  </PolyData>\n"
      "  <AppendedData encoding=\"raw\">\n   _0123\n  </AppendedData>\n</VTKFile>\n" },
    { "cells_beyond_everything.vtp", [] {
        std::string vtp = VTP();
        const std::size_t at = vtp.find("NumberOfPolys=\"4\"");
        return vtp.replace(at, 18, "NumberOfVerts=\"9223372036854775807\" NumberOfPolys=\"4\"");
      }() },
    { "field_without_type.vtp",
      VTPWithField("      <DataArray Name=\"x\" NumberOfTuples=\"1\" format=\"ascii\">1"
                   "</DataArray>\n") },
    { "empty.ply", "" },
    { "empty.stl", "" },
    { "empty.vtp", "" },
    // Issue 50: what crashed, stalled or read silently wrong.
    { "nested_20000.vtp", VTPWithMarkup(Nested(20000)) },
    { "attribute_2mib.vtp", VTPWithMarkup("<a x=\"" + std::string(2 << 20, 'y') + "\"/>") },
    { "comment_2mib.vtp", VTPWithMarkup("<!--" + std::string(2 << 20, 'y') + "-->") },
    { "doctype.vtp", "<?xml version=\"1.0\"?>\n<!DOCTYPE VTKFile [<!ENTITY a \"b\">]>\n" + vtp.substr(22) },
    { "more_offsets_than_cells.vtp", [] {
        std::string vtp = VTP();
        return vtp.replace(vtp.find("NumberOfPolys=\"4\""), 17, "NumberOfPolys=\"3\"");
      }() },
    { "nan.obj", OBJWithCoordinate("nan") },
    { "inf.obj", OBJWithCoordinate("-inf") },
    { "fewer_faces_declared.ply", DoublePLY(3, 1.0) },
    { "fewer_faces_declared_binary.ply", BinaryPLYDeclaring(3) },
    { "fewer_faces_declared.off", OFF().replace(4, 5, "4 3 0") },
    { "doubles_beyond_float.ply", DoublePLY(4, 1e300) },
    { "doubles_below_float.ply", DoublePLY(4, 1e-300) },
    // Found by fuzzing: vtkPolyDataReader crashed on both.
    { "points_of_unknown_type.vtk", [] {
        std::string vtk = LegacyVTK();
        return vtk.replace(vtk.find("4 float"), 7, "4 floatFIELD");
      }() },
    { "field_block_cut_short.vtk", LegacyVTK().substr(0, LegacyVTK().find("POINTS")) + "FIELD FieldData 2\n" },
    { "field_values_cut_short.vtk", LegacyVTKWithField("FIELD FieldData 1\nx 1 3 int\n2 3\n") },
    { "field_keyword_prefix.vtk", LegacyVTKWithField("FIELDv 2 2 double\n1 2\n3 4\n") },
  };
}

/// Inputs that read well but hold no triangle: one line, exit status 1.
std::vector<Case> FilesWithoutTriangles()
{
  return {
    { "no_faces_declared.ply", DoublePLY(0, 1.0).substr(0, DoublePLY(0, 1.0).find("3 0 2 1")) },
    { "points_only.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n" },
    { "lines_only.vtk", "# vtk DataFile Version 3.0\nlines\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n"
                        "0 0 0 1 0 0 0 1 0\nLINES 1 4\n3 0 1 2\n" },
  };
}

bool WriteFile(const std::string& path, const std::string& bytes)
{
  std::ofstream out(path, std::ios::binary);
  out << bytes;
  return static_cast<bool>(out);
}

/// Runs tool on input; its exit status (a signal as 128 + its number) and standard error.
int Run(const std::string& tool, const std::string& input, const std::string& output,
  const std::string& errors, std::string& text)
{
  const pid_t child = fork();
  if (child == 0)
  {
    alarm(10); // any file is read or refused within 10 s
    const int file = open(errors.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(file, 2);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    execl(tool.c_str(), tool.c_str(), "--method", "octree", input.c_str(), output.c_str(),
      static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  waitpid(child, &status, 0);
  std::ifstream in(errors);
  text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : WEXITSTATUS(status);
}

void ExpectRead(const std::string& tool, const std::string& directory, const Case& sound)
{
  const std::string input = directory + "/" + sound.Name;
  std::string errors;
  WriteFile(input, sound.Bytes);
  const int status = Run(tool, input, directory + "/out.vtp", directory + "/stderr.txt", errors);
  if (status != 0)
  {
    Fail(sound.Name + ": exit " + std::to_string(status) + ", " + errors);
  }
}

/// A sound file read with warning among the messages.
void ExpectWarning(const std::string& tool, const std::string& directory, const std::string& name,
  const std::string& warning)
{
  const std::string input = directory + "/" + name;
  std::string errors;
  const int status = Run(tool, input, directory + "/out.vtp", directory + "/stderr.txt", errors);
  if (status != 0 || errors.find(warning) == std::string::npos)
  {
    Fail(name + ": exit " + std::to_string(status) + ", no warning '" + warning + "' in: " + errors);
  }
}

void ExpectOneLine(const std::string& tool, const std::string& directory, const std::string& name,
  const std::string& reason = "cannot read '")
{
  const std::string input = directory + "/" + name;
  const std::string start = "meshsimplify: " + reason + input + (reason.empty() ? ": " : "': ");
  std::string errors;
  const int status = Run(tool, input, directory + "/out.vtp", directory + "/stderr.txt", errors);
  const bool oneLine = !errors.empty() && errors.find('\n') == errors.size() - 1;
  if (status != 1 || !oneLine || errors.rfind(start, 0) != 0 || errors.size() <= start.size() + 1)
  {
    Fail(name + ": exit " + std::to_string(status) + ", standard error: " + errors);
  }
}
}

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::fprintf(stderr, "usage: TestMeshSimplifyBadFiles <meshsimplify> <work directory>\n");
    return 2;
  }
  const std::string tool = argv[1], directory = argv[2];
  mkdir(directory.c_str(), 0755);
  for (const Case& sound : SoundFiles())
  {
    ExpectRead(tool, directory, sound);
  }
  for (const Case& damaged : DamagedFiles())
  {
    WriteFile(directory + "/" + damaged.Name, damaged.Bytes);
    ExpectOneLine(tool, directory, damaged.Name);
  }
  for (const Case& empty : FilesWithoutTriangles())
  {
    WriteFile(directory + "/" + empty.Name, empty.Bytes);
    ExpectOneLine(tool, directory, empty.Name, "");
  }
  ExpectWarning(tool, directory, "sound_with_a_line.off",
    "meshsimplify: warning: Ignoring 1 polygon or strip of fewer than 3 points.\n");
  // A directory named like a mesh.
  mkdir((directory + "/directory.ply").c_str(), 0755);
  ExpectOneLine(tool, directory, "directory.ply");
  std::printf("%d failed\n", failures);
  return failures == 0 ? 0 : 1;
}
