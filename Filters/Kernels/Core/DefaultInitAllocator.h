// An allocator whose value-less construct() default-initialises, so that resize() of a vector of
// plain numbers leaves the new elements unwritten.
//
// Why: the merged mesh's tet array of a 6 M-tet output is 192 MB. A plain vector's resize()
// zero-fills it on the calling thread, and that first touch also takes every page fault there;
// the parallel copy that overwrites it then scales, but the fill does not (about 0.1 s of the
// merge at 1 and at 2 threads). Unwritten, the pages are first touched by the parallel copy.
#ifndef cgmesh_DefaultInitAllocator_h
#define cgmesh_DefaultInitAllocator_h

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace cgmesh
{

template <typename T>
class DefaultInitAllocator : public std::allocator<T>
{
public:
  template <typename U>
  struct rebind
  {
    using other = DefaultInitAllocator<U>;
  };

  DefaultInitAllocator() = default;
  template <typename U>
  DefaultInitAllocator(const DefaultInitAllocator<U>& other) noexcept
    : std::allocator<T>(other)
  {
  }

  template <typename U>
  void construct(U* place) noexcept(std::is_nothrow_default_constructible<U>::value)
  {
    ::new (static_cast<void*>(place)) U;
  }

  template <typename U, typename... Arguments>
  void construct(U* place, Arguments&&... arguments)
  {
    ::new (static_cast<void*>(place)) U(std::forward<Arguments>(arguments)...);
  }
};

// A vector of plain values for arrays of millions that are always written after they are sized.
template <typename T>
using UnfilledVector = std::vector<T, DefaultInitAllocator<T>>;

} // namespace cgmesh

#endif
