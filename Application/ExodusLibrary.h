// What the Exodus reader and writer share (ExodusReader.cxx, ExodusWriter.cxx): libexodus's
// side numbering, its error text and an open file's lifetime.
#ifndef cgmesh_ExodusLibrary_h
#define cgmesh_ExodusLibrary_h

#include "vtk_exodusII.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace cgmesh
{
namespace exodus
{

// The corners of each side of an Exodus TETRA (local node numbers from 0), in the order whose
// normal points out of a positively oriented tetrahedron, as the Exodus II manual numbers them.
inline constexpr int TetSideCorners[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 0, 3, 2 }, { 0, 2, 1 } };

inline constexpr int MaximumNameLength = 255; // below netCDF's NC_MAX_NAME

// The library's last message, or `fallback` when it left none.
inline std::string exodusError(const std::string& fallback)
{
  const char* message = nullptr;
  const char* function = nullptr;
  int code = 0;
  ex_get_err(&message, &function, &code);
  return message && *message ? std::string(message) : fallback;
}

// An open Exodus file, closed when it goes out of scope.
class ExodusFile
{
public:
  explicit ExodusFile(int id)
    : Id(id)
  {
  }
  ~ExodusFile()
  {
    if (this->Id >= 0)
      ex_close(this->Id);
  }
  ExodusFile(const ExodusFile&) = delete;
  ExodusFile& operator=(const ExodusFile&) = delete;
  int id() const { return this->Id; }
  // Closes now, so that a write error shows before the file is renamed into place.
  bool close()
  {
    const int result = ex_close(this->Id);
    this->Id = -1;
    return result >= 0;
  }

private:
  int Id;
};

inline std::string lowerCase(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

} // namespace exodus
} // namespace cgmesh

#endif
