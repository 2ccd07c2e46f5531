/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshUninitializedAllocator.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMeshUninitializedAllocator
 * @brief   a std::allocator whose resize() leaves plain values unwritten
 *
 * The mesh builder's arrays are sized, then written in parallel by the stage that sized them.
 * A std::vector's resize() first writes every new value (zero) on the calling thread: at a
 * billion tetrahedra that is tens of gigabytes written, and their pages first touched, on one
 * thread before the parallel loop even starts. With this allocator resize() constructs plain
 * values by default-initialization (no write), so memory is first touched by the threads that
 * fill it; resize(n, value) and assign() still write the value. Every stage writes what it
 * sizes (vtkTetMeshBuildState.h); where a value is needed it fills in parallel (vtkSMPTools::Fill).
 *
 * Large blocks are also marked for transparent huge pages (vtkTetMeshHugePages): their first
 * touch is then one page fault per 2 MiB instead of one per 4 KiB, which on virtual machines
 * costs more than the build's own work.
 */
#ifndef vtkTetMeshUninitializedAllocator_h
#define vtkTetMeshUninitializedAllocator_h

#include "vtkTetMeshHugePages.h" // For vtkTetMeshHugePages::Advise

#include <cstddef> // For size_t
#include <memory>  // For std::allocator
#include <new>     // For placement new
#include <utility> // For std::forward
#include <vector>  // For std::vector

template <typename T>
class vtkTetMeshUninitializedAllocator : public std::allocator<T>
{
public:
  template <typename U>
  struct rebind
  {
    using other = vtkTetMeshUninitializedAllocator<U>;
  };
  vtkTetMeshUninitializedAllocator() noexcept = default;
  template <typename U>
  vtkTetMeshUninitializedAllocator(const vtkTetMeshUninitializedAllocator<U>&) noexcept
  {
  }
  T* allocate(size_t n)
  {
    T* p = std::allocator<T>::allocate(n);
    vtkTetMeshHugePages::Advise(p, n * sizeof(T));
    return p;
  }
  /// Default construction: default-initialization, no value written for plain types.
  template <typename U>
  void construct(U* p) noexcept(noexcept(::new (static_cast<void*>(p)) U))
  {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

/// The builder's and the mesh's arrays.
template <typename T>
using vtkTetMeshVector = std::vector<T, vtkTetMeshUninitializedAllocator<T>>;

#endif
// VTK-HeaderTest-Exclude: vtkTetMeshUninitializedAllocator.h
