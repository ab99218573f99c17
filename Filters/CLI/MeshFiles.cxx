// SPDX-License-Identifier: BSD-3-Clause
#include "MeshFiles.h"

#include "MeshFileChecks.h"
#include "vtkOFFMeshReader.h"
#include "vtkOFFWriter.h"

#include "vtkCellArray.h"
#include "vtkFieldData.h"
#include "vtkGLTFWriter.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPNGWriter.h"
#include "vtkStringArray.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkLogger.h"
#include "vtkOBJReader.h"
#include "vtkOBJWriter.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPLYReader.h"
#include "vtkPLYWriter.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkPolyDataWriter.h"
#include "vtkSTLReader.h"
#include "vtkSTLWriter.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include "WholeFile.h"

#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <exception>
#include <new>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

namespace meshfiles
{
namespace
{
/// Takes the messages VTK would print (its warnings and errors, through the output window
/// and the logger) while it lives, and keeps the first as a reason.
class MessageCollector : public vtkOutputWindow
{
public:
  static MessageCollector* New();
  vtkTypeMacro(MessageCollector, vtkOutputWindow);

  void DisplayText(const char* text) override
  {
    if (this->First.empty() && text)
    {
      this->First = Reason(text);
    }
  }

  std::string First;

private:
  /// The message line of VTK's "ERROR: In file, line N\nvtkClass (0x...): message\n\n", or of
  /// a generic warning, without the class and address.
  static std::string Reason(const std::string& text)
  {
    std::string line = text.substr(0, text.find('\n'));
    if (line.find(": In ") != std::string::npos && text.find('\n') != std::string::npos)
    {
      const std::size_t next = text.find('\n') + 1;
      line = text.substr(next, text.find('\n', next) - next);
    }
    const std::size_t address = line.find(" (0x");
    const std::size_t close = line.find("): ");
    if (address != std::string::npos && close != std::string::npos && address < close)
    {
      line = line.substr(close + 3);
    }
    return line.empty() ? "VTK reported an empty message" : line;
  }
};
vtkStandardNewMacro(MessageCollector);

/// While it lives, VTK prints nothing: its messages go to a MessageCollector.
class QuietVTK
{
public:
  QuietVTK()
    : Previous(vtkOutputWindow::GetInstance())
    , Verbosity(vtkLogger::GetCurrentVerbosityCutoff())
  {
    vtkOutputWindow::SetInstance(this->Collector);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~QuietVTK()
  {
    vtkOutputWindow::SetInstance(this->Previous);
    vtkLogger::SetStderrVerbosity(this->Verbosity);
  }
  QuietVTK(const QuietVTK&) = delete;
  QuietVTK& operator=(const QuietVTK&) = delete;

  /// The first message VTK gave, or "".
  const std::string& FirstMessage() const { return this->Collector->First; }

private:
  vtkNew<MessageCollector> Collector;
  vtkSmartPointer<vtkOutputWindow> Previous;
  vtkLogger::Verbosity Verbosity;
};

template <typename Reader>
vtkSmartPointer<vtkAlgorithm> NewReader(const std::string& path)
{
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(path.c_str());
  return reader;
}

template <typename Writer>
void NoSettings(Writer*)
{
}

void BinaryPLY(vtkPLYWriter* writer)
{
  writer->SetFileTypeToBinary();
}

void BinarySTL(vtkSTLWriter* writer)
{
  writer->SetFileTypeToBinary();
}

void InlineBinaryVTP(vtkXMLPolyDataWriter* writer)
{
  // Inline binary: VTK 9.2's reader rejects some appended base64 files its writer makes.
  writer->SetDataModeToBinary();
}

/// Writes mesh to path with a Writer set up by Configure.
template <typename Writer, void (*Configure)(Writer*) = NoSettings<Writer>>
bool Write(vtkPolyData* mesh, const std::string& path)
{
  vtkNew<Writer> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(mesh);
  Configure(writer);
  return writer->Write() == 1;
}

/// As Write, through the Writer's output string: VTK's XML writer frees an invalid pointer
/// when a write to its file fails, so it writes no file.
template <typename Writer, void (*Configure)(Writer*) = NoSettings<Writer>>
bool WriteThroughString(vtkPolyData* mesh, const std::string& path)
{
  vtkNew<Writer> writer;
  writer->SetInputData(mesh);
  writer->WriteToOutputStringOn();
  Configure(writer);
  std::ofstream out(path, std::ios::binary);
  return writer->Write() == 1 && out << writer->GetOutputString() && out.flush();
}

/// A format by extension: the check of its files (none for OFF: our reader checks every
/// line itself), its reader and its writer, and whether that writer writes whole files itself
/// (ours does; VTK's are given memory to write to, see WriteThroughMemory).
struct MeshFormat
{
  const char* Extension;
  std::string (*Check)(const std::string& path);
  vtkSmartPointer<vtkAlgorithm> (*NewReader)(const std::string& path);
  bool (*Write)(vtkPolyData* mesh, const std::string& path);
  bool WritesWholeFiles;
};

const MeshFormat Formats[] = {
  { "off", nullptr, NewReader<vtkOFFMeshReader>, Write<vtkOFFWriter>, true },
  { "ply", CheckPLY, NewReader<vtkPLYReader>, Write<vtkPLYWriter, BinaryPLY>, false },
  { "stl", CheckSTL, NewReader<vtkSTLReader>, Write<vtkSTLWriter, BinarySTL>, false },
  { "obj", CheckOBJ, NewReader<vtkOBJReader>, Write<vtkOBJWriter>, false },
  { "vtp", CheckVTP, NewReader<vtkXMLPolyDataReader>,
    WriteThroughString<vtkXMLPolyDataWriter, InlineBinaryVTP>, false },
  { "vtk", CheckLegacyVTK, NewReader<vtkPolyDataReader>, WriteThroughString<vtkPolyDataWriter>,
    false },
};
const char* Extensions = "(.off .ply .stl .obj .vtp .vtk)";

const MeshFormat* FindFormat(const std::string& path)
{
  const std::size_t dot = path.rfind('.');
  std::string extension = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(), ::tolower);
  for (const MeshFormat& format : Formats)
  {
    if (extension == format.Extension)
    {
      return &format;
    }
  }
  return nullptr;
}

/// What every input must be before its format is looked at, in order; the first that fails
/// is the reason.
struct FileCheck
{
  const char* Failure;
  bool (*Passes)(const std::string& path);
};

const FileCheck CommonChecks[] = {
  { "no such file",
    [](const std::string& path) {
      std::error_code error;
      return std::filesystem::exists(path, error);
    } },
  { "not a regular file (a directory, a device or a pipe)",
    [](const std::string& path) {
      std::error_code error;
      return std::filesystem::is_regular_file(path, error);
    } },
  { "cannot be opened", [](const std::string& path) { return std::ifstream(path).is_open(); } },
  { "empty file",
    [](const std::string& path) {
      std::error_code error;
      return std::filesystem::file_size(path, error) > 0 && !error;
    } },
};

/// The first failed check of the file, "" when it may be read.
std::string CheckFile(const MeshFormat& format, const std::string& path)
{
  for (const FileCheck& check : CommonChecks)
  {
    if (!check.Passes(path))
    {
      return check.Failure;
    }
  }
  return format.Check ? format.Check(path) : "";
}

/// The first cell of cells whose offsets are out of order or whose point ids name no point.
template <typename Array>
std::string CheckCellIds(Array* offsets, Array* connectivity, vtkIdType points, const char* kind)
{
  const vtkIdType count = offsets->GetNumberOfValues() - 1;
  if (count < 0 || offsets->GetValue(0) != 0 ||
    offsets->GetValue(count) != connectivity->GetNumberOfValues())
  {
    return std::string("the ") + kind + " offsets do not span their point ids";
  }
  for (vtkIdType cell = 0; cell < count; ++cell)
  {
    if (offsets->GetValue(cell + 1) < offsets->GetValue(cell))
    {
      return std::string("the ") + kind + " offsets decrease at cell " + std::to_string(cell);
    }
    for (vtkIdType k = offsets->GetValue(cell); k < offsets->GetValue(cell + 1); ++k)
    {
      const vtkIdType id = connectivity->GetValue(k);
      if (id < 0 || id >= points)
      {
        return std::string(kind) + " cell " + std::to_string(cell) + " names point " +
          std::to_string(id) + " of " + std::to_string(points);
      }
    }
  }
  return "";
}

/// The mesh's cells must be sound for the filters: readers pass on what the file says.
std::string CheckCells(vtkPolyData* mesh)
{
  const struct
  {
    vtkCellArray* Cells;
    const char* Kind;
  } kinds[] = { { mesh->GetVerts(), "vertex" }, { mesh->GetLines(), "line" },
    { mesh->GetPolys(), "polygon" }, { mesh->GetStrips(), "strip" } };
  for (const auto& kind : kinds)
  {
    vtkCellArray* cells = kind.Cells;
    const std::string problem = !cells ? ""
      : cells->IsStorage64Bit()
      ? CheckCellIds(cells->GetOffsetsArray64(), cells->GetConnectivityArray64(),
          mesh->GetNumberOfPoints(), kind.Kind)
      : CheckCellIds(cells->GetOffsetsArray32(), cells->GetConnectivityArray32(),
          mesh->GetNumberOfPoints(), kind.Kind);
    if (!problem.empty())
    {
      return problem;
    }
  }
  return "";
}

/// A file in memory (memfd), named for writers by a link "mesh.<extension>" in a private
/// folder of the temporary directory (vtkPLYWriter adds ".ply" to a name without it).
class MemoryFile
{
public:
  explicit MemoryFile(const std::string& extension)
    : Descriptor(memfd_create("meshsimplify-output", MFD_CLOEXEC))
  {
    const char* temporary = std::getenv("TMPDIR");
    std::string folder = std::string(temporary && *temporary ? temporary : "/tmp") + "/meshsimplify-XXXXXX";
    if (this->Descriptor >= 0 && mkdtemp(&folder[0]))
    {
      this->Folder = folder;
      const std::string link = folder + "/mesh." + extension;
      const std::string target = "/proc/self/fd/" + std::to_string(this->Descriptor);
      this->Link = symlink(target.c_str(), link.c_str()) == 0 ? link : "";
    }
  }
  ~MemoryFile()
  {
    unlink(this->Link.c_str());
    rmdir(this->Folder.c_str());
    close(this->Descriptor);
  }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;

  /// Its name for writers; "" when it could not be made (errno says why).
  const std::string& Path() const { return this->Link; }
  int Descriptor;

private:
  std::string Folder, Link;
};

/// Runs the reader of a file that passed its checks; nullptr with the reason on failure.
vtkSmartPointer<vtkPolyData> RunReader(
  const MeshFormat& format, const std::string& path, const QuietVTK& quiet, std::string& reason)
{
  vtkSmartPointer<vtkAlgorithm> reader = format.NewReader(path);
  reader->Update();
  vtkPolyData* output = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  reason = quiet.FirstMessage();
  if (reason.empty() && (reader->GetErrorCode() != 0 || !output))
  {
    reason = "the reader failed";
  }
  if (reason.empty())
  {
    reason = CheckCells(output);
  }
  if (!reason.empty())
  {
    return nullptr;
  }
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(output);
  return copy;
}

/// The ids of 32-bit integers where they fit (every id names one of points points, as the
/// reader's cells were checked): 16 bytes a triangle less for as long as the run lasts. A plain
/// copy: vtkCellArray::ConvertTo32BitStorage takes 1.1 s on 4.8 M triangles, this 0.05 s.
void UseCompactIds(vtkCellArray* cells, vtkIdType points)
{
  if (!cells->IsStorage64Bit() || points > VTK_INT_MAX ||
    cells->GetNumberOfConnectivityIds() > VTK_INT_MAX)
  {
    return;
  }
  const auto narrowed = [](vtkTypeInt64Array* wide) {
    auto narrow = vtkSmartPointer<vtkTypeInt32Array>::New();
    narrow->SetNumberOfValues(wide->GetNumberOfValues());
    std::copy(wide->GetPointer(0), wide->GetPointer(0) + wide->GetNumberOfValues(), narrow->GetPointer(0));
    return narrow;
  };
  cells->SetData(narrowed(cells->GetOffsetsArray64()), narrowed(cells->GetConnectivityArray64()));
}

/// Seconds a reader may take on a file: 5, or 1 per MB of the file for larger ones (VTK's
/// slowest readers take about 0.02 s per MB), so that any file under 5 MB is read or refused
/// within 5 s and none hangs.
unsigned ReadTimeLimit(const std::string& path)
{
  std::error_code error;
  const std::uintmax_t megabytes = std::filesystem::file_size(path, error) >> 20;
  return static_cast<unsigned>(std::min<std::uintmax_t>(std::max<std::uintmax_t>(5, megabytes), 1u << 20));
}

/// The child's part of ReadInChild: the time limit, the memory limit (the machine's memory; not
/// under AddressSanitizer, which reserves far more address space), the reader, then the mesh
/// as an uncompressed, raw-appended VTP into handBack and the first message into report.
[[noreturn]] void ReadAsChild(
  const MeshFormat& format, const std::string& path, const std::string& handBack, int report)
{
  // The limit works whatever the parent did with SIGALRM (a fuzzer installs its own handler).
  std::signal(SIGALRM, SIG_DFL);
  sigset_t alarmOnly;
  sigemptyset(&alarmOnly);
  sigaddset(&alarmOnly, SIGALRM);
  sigprocmask(SIG_UNBLOCK, &alarmOnly, nullptr);
  alarm(ReadTimeLimit(path));
#ifndef __SANITIZE_ADDRESS__
  const rlim_t memory = static_cast<rlim_t>(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGESIZE);
  const struct rlimit limit = { memory, memory };
  setrlimit(RLIMIT_AS, &limit);
#endif
  std::string reason;
  try
  {
    QuietVTK quiet;
    vtkSmartPointer<vtkPolyData> mesh = RunReader(format, path, quiet, reason);
    if (mesh)
    {
      vtkNew<vtkXMLPolyDataWriter> writer;
      writer->SetInputData(mesh);
      writer->SetFileName(handBack.c_str());
      writer->SetDataModeToAppended();
      writer->EncodeAppendedDataOff();
      writer->SetCompressorTypeToNone();
      writer->SetHeaderTypeToUInt64();
      reason = writer->Write() == 1 ? quiet.FirstMessage() : "the mesh could not be handed back";
    }
  }
  catch (const std::bad_alloc&)
  {
    reason = "reading it takes more memory than the machine has";
  }
  catch (const std::exception& exception)
  {
    reason = std::string("the reader failed: ") + exception.what();
  }
  const bool sent = write(report, reason.data(), reason.size()) == static_cast<ssize_t>(reason.size());
  _exit(reason.empty() && sent ? 0 : 1);
}

/// What a child's end says: "" when it read the file, else the reason.
std::string ChildFailure(int status, const std::string& message, unsigned seconds)
{
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
  {
    return "reading took longer than " + std::to_string(seconds) + " s";
  }
  if (WIFSIGNALED(status))
  {
    return std::string("the VTK reader crashed on it (") + strsignal(WTERMSIG(status)) + ")";
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
  {
    return message.empty() ? "the reader failed" : message;
  }
  return "";
}

/// The reader runs in a child process, so that what a VTK reader does with a file that passed
/// every check (fuzzing keeps finding crashes in vtkPolyDataReader) costs the child only: a
/// crash, a hang past ReadTimeLimit or memory beyond the machine's becomes the reason. The
/// child hands the mesh back as a raw VTP in shared memory (a memfd): a fifth to a third of the
/// read on top (0.19 s on a 0.95 s read of a 2 M-triangle VTP, 0.6 s on a 2.3 s read of a
/// 4.8 M-triangle PLY).
vtkSmartPointer<vtkPolyData> ReadInChild(const MeshFormat& format, const std::string& path, std::string& reason)
{
  MemoryFile handBack("vtp");
  int report[2];
  if (handBack.Path().empty() || pipe(report) != 0)
  {
    reason = std::string("no process to read in: ") + std::strerror(errno);
    return nullptr;
  }
  std::fflush(nullptr);
  const pid_t child = fork();
  if (child == 0)
  {
    close(report[0]);
    ReadAsChild(format, path, handBack.Path(), report[1]);
  }
  close(report[1]);
  std::string message;
  char buffer[4096];
  for (ssize_t got = 0; (got = read(report[0], buffer, sizeof(buffer))) > 0;)
  {
    message.append(buffer, static_cast<std::size_t>(got));
  }
  close(report[0]);
  int status = 0;
  reason = child < 0 ? std::string("no process to read in: ") + std::strerror(errno)
    : waitpid(child, &status, 0) < 0 ? "the reading process was lost"
                                      : ChildFailure(status, message, ReadTimeLimit(path));
  if (!reason.empty())
  {
    return nullptr;
  }
  QuietVTK quiet;
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(handBack.Path().c_str());
  reader->Update();
  reason = quiet.FirstMessage();
  if (!reason.empty())
  {
    return nullptr;
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(reader->GetOutput());
  for (vtkCellArray* cells : { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips() })
  {
    UseCompactIds(cells, mesh->GetNumberOfPoints());
  }
  return mesh;
}

/// The bytes of a file descriptor from its start, copied to out; false when a read or a write
/// fails.
bool CopyBytes(int from, std::FILE* out)
{
  std::vector<char> buffer(1 << 20);
  if (lseek(from, 0, SEEK_SET) != 0)
  {
    return false;
  }
  for (ssize_t got = 0; (got = read(from, buffer.data(), buffer.size())) != 0;)
  {
    if (got < 0 || std::fwrite(buffer.data(), 1, static_cast<std::size_t>(got), out) !=
        static_cast<std::size_t>(got))
    {
      return false;
    }
  }
  return true;
}

/// Why bytes written to a file may have been cut short ("" when not): the size reached the
/// process's file size limit (ulimit -f), where writes fail with no error VTK would see.
std::string SizeLimitReached(int file)
{
  struct stat status;
  struct rlimit limit;
  if (fstat(file, &status) != 0 || getrlimit(RLIMIT_FSIZE, &limit) != 0 ||
    limit.rlim_cur == RLIM_INFINITY || static_cast<rlim_t>(status.st_size) < limit.rlim_cur)
  {
    return "";
  }
  return "the output reaches the file size limit of " + std::to_string(limit.rlim_cur) +
    " bytes (ulimit -f)";
}

/// VTK 9.2's writers check few of their writes (the PLY and OBJ writers none, and the XML
/// writer frees an invalid pointer on a full disk), so each writes into memory, whose bytes
/// then reach the disk through WriteWholeFile, every write checked.
bool WriteThroughMemory(
  const MeshFormat& format, vtkPolyData* mesh, const std::string& path, std::string& reason)
{
  MemoryFile memory(format.Extension);
  if (memory.Path().empty())
  {
    reason = std::string("no file in memory to write to: ") + std::strerror(errno);
    return false;
  }
  QuietVTK quiet;
  const bool written = format.Write(mesh, memory.Path());
  reason = SizeLimitReached(memory.Descriptor);
  if (reason.empty() && (!written || !quiet.FirstMessage().empty()))
  {
    reason = quiet.FirstMessage().empty() ? "the writer failed" : quiet.FirstMessage();
  }
  return reason.empty() &&
    meshsimp::WriteWholeFile(
      path, [&memory](std::FILE* out) { return CopyBytes(memory.Descriptor, out); }, reason);
}
}

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path, std::string& error)
{
  const MeshFormat* format = FindFormat(path);
  if (!format)
  {
    error = "cannot read '" + path + "': unknown extension " + Extensions;
    return nullptr;
  }
  QuietVTK quiet;
  std::string reason = CheckFile(*format, path);
  if (reason.empty())
  {
    reason = quiet.FirstMessage(); // a check that asked VTK (the XML parser) may have failed
  }
  vtkSmartPointer<vtkPolyData> mesh;
  if (reason.empty())
  {
    mesh = ReadInChild(*format, path, reason);
  }
  if (!mesh)
  {
    if (reason.rfind(path + ": ", 0) == 0)
    {
      reason.erase(0, path.size() + 2); // our OFF reader names the file too
    }
    error = "cannot read '" + path + "': " + reason;
  }
  return mesh;
}

bool WriteMesh(vtkPolyData* mesh, const std::string& path, std::string& error)
{
  const MeshFormat* format = FindFormat(path);
  if (!format)
  {
    error = "cannot write '" + path + "': unknown extension " + Extensions;
    return false;
  }
  std::string reason;
  if (!format->WritesWholeFiles)
  {
    if (WriteThroughMemory(*format, mesh, path, reason))
    {
      return true;
    }
  }
  else
  {
    QuietVTK quiet;
    if (format->Write(mesh, path) && quiet.FirstMessage().empty())
    {
      return true;
    }
    reason = quiet.FirstMessage().empty() ? "the writer failed" : quiet.FirstMessage();
  }
  if (reason.rfind("cannot write " + path + ": ", 0) == 0)
  {
    reason.erase(0, path.size() + 15); // our OFF writer names the file too
  }
  error = "cannot write '" + path + "': " + reason;
  return false;
}

namespace
{
/// Writes a textured mesh's files into folder, named after file: the texture as <stem>.png and,
/// for .obj and .gltf/.glb, the mesh (the .obj's .mtl naming the .png relatively; glTF with the
/// texture embedded). The names written are added to names.
bool WriteTexturedFiles(vtkPolyData* mesh, vtkImageData* texture, const std::filesystem::path& file,
  const std::filesystem::path& folder, const std::string& extension, std::vector<std::string>& names)
{
  const std::string image = file.stem().string() + ".png";
  vtkNew<vtkPNGWriter> png;
  png->SetInputData(texture);
  png->SetCompressionLevel(1); // zlib's fastest, as OpenCV's default: much quicker than VTK's 5, a little larger
  png->SetFileName((folder / image).string().c_str());
  png->Write();
  if (png->GetErrorCode() != 0)
  {
    return false;
  }
  if (extension == ".gltf" || extension == ".glb")
  {
    // VTK 9.2's glTF writer takes a texture by name from a block of a block's field data.
    vtkNew<vtkPolyData> textured;
    textured->ShallowCopy(mesh);
    vtkNew<vtkStringArray> name;
    name->SetName("texture_uri");
    name->InsertNextValue(image);
    textured->GetFieldData()->AddArray(name);
    vtkNew<vtkMultiBlockDataSet> inner, scene;
    inner->SetBlock(0, textured);
    scene->SetBlock(0, inner);
    vtkNew<vtkGLTFWriter> writer;
    writer->SetInputData(scene);
    writer->SetFileName((folder / file.filename()).string().c_str());
    writer->SetTextureBaseDirectory(folder.string().c_str());
    writer->SaveTexturesOn();
    writer->SetInlineData(true);
    writer->Write();
    names.push_back(file.filename().string());
    return true;
  }
  names.push_back(image);
  if (extension == ".obj")
  {
    vtkNew<vtkOBJWriter> writer;
    writer->SetInputData(mesh);
    writer->SetTextureFileName(image.c_str());
    writer->SetFileName((folder / file.filename()).string().c_str());
    writer->Write();
    names.push_back(file.filename().string());
    names.push_back(file.stem().string() + ".mtl");
    return writer->GetErrorCode() == 0;
  }
  return true;
}
} // namespace

bool WriteTexturedMesh(vtkPolyData* mesh, vtkImageData* texture, const std::string& path, std::string& error)
{
  const std::filesystem::path file(path);
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension != ".obj" && extension != ".gltf" && extension != ".glb" && !WriteMesh(mesh, path, error))
  {
    return false;
  }
  // Each file is made in a folder of its own, then put in place whole (see WholeFile.h).
  std::error_code failure;
  const std::filesystem::path folder =
    std::filesystem::temp_directory_path(failure) / ("meshsimplify-" + std::to_string(getpid()) + "-textured");
  std::filesystem::create_directories(folder, failure);
  std::vector<std::string> names;
  QuietVTK quiet;
  bool written = !failure && WriteTexturedFiles(mesh, texture, file, folder, extension, names) && quiet.FirstMessage().empty();
  std::string reason = failure ? failure.message() : quiet.FirstMessage().empty() ? "the writer failed" : quiet.FirstMessage();
  for (std::size_t i = 0; written && i < names.size(); ++i)
  {
    std::ifstream made(folder / names[i], std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(made)), std::istreambuf_iterator<char>());
    written = made.good() || made.eof();
    written = written && meshsimp::WriteWholeFile((file.parent_path() / names[i]).string(), [&](std::FILE* out) {
      return std::fwrite(bytes.data(), 1, bytes.size(), out) == bytes.size();
    }, reason);
  }
  std::filesystem::remove_all(folder, failure);
  if (!written)
  {
    error = "cannot write '" + path + "' with its texture: " + reason;
  }
  return written;
}

} // namespace meshfiles
