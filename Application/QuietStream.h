// Silences a standard stream while a library that talks on it runs: tetgenio announces every file
// on stdout, libexodus prints its errors on stderr whatever its options say. The command's own
// output stays clean; the caller reports failures itself.
#ifndef cgmesh_QuietStream_h
#define cgmesh_QuietStream_h

#include <cstdio>
#include <fcntl.h>
#include <unistd.h>

namespace cgmesh
{

class QuietStream
{
public:
  // `stream` is stdout or stderr, `descriptor` its file descriptor.
  QuietStream(std::FILE* stream, int descriptor)
    : Stream(stream)
    , Descriptor(descriptor)
  {
    std::fflush(this->Stream);
    this->Saved = ::dup(this->Descriptor);
    const int devNull = ::open("/dev/null", O_WRONLY);
    if (devNull >= 0)
    {
      ::dup2(devNull, this->Descriptor);
      ::close(devNull);
    }
  }
  ~QuietStream()
  {
    std::fflush(this->Stream);
    if (this->Saved >= 0)
    {
      ::dup2(this->Saved, this->Descriptor);
      ::close(this->Saved);
    }
  }
  QuietStream(const QuietStream&) = delete;
  QuietStream& operator=(const QuietStream&) = delete;

private:
  std::FILE* Stream;
  int Descriptor;
  int Saved = -1;
};

} // namespace cgmesh

#endif
