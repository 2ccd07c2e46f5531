/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetGenTerminate.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// TetGen's error exit, replaced.
//
// TetGen 1.5.0 (Debian's libtet 1.5.0-5, built with TETLIBRARY) reports every error through
// the inline function terminatetetgen(m, code) of tetgen.h, which calls m->freememory() and then
// throws the code. But `m` is the local tetgenmesh of tetrahedralize(), whose destructor calls
// freememory() again while the exception unwinds, and freememory() does not reset its pointers:
// every TetGen error ends in a double free (SIGSEGV in tetgenmesh::memorypool::~memorypool(),
// seen here with a self-intersecting surface).
//
// libtet calls terminatetetgen() through its PLT (it is an exported weak symbol), so the
// definition below, exported by vtkFiltersTetGen, which is searched before libtet, is the one
// that runs: it only throws, and the destructor frees the mesh once. This file must not include
// tetgen.h, whose inline definition of the same function would clash with this one.
// TestTetGenMesherErrors exercises the path (TetGen error 3 with CheckSelfIntersections off).

class tetgenmesh;

__attribute__((visibility("default"))) void terminatetetgen(tetgenmesh*, int code)
{
  throw code;
}
