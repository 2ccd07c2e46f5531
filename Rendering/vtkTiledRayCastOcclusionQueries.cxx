/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastOcclusionQueries.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastOcclusionQueries.h"

#include "vtk_glew.h"

//------------------------------------------------------------------------------
unsigned int vtkTiledRayCastOcclusionQueries::Begin()
{
  if (this->NextFree == this->Queries.size())
  {
    // Grow the pool in blocks: a frame uses a few queries per tile and layer.
    const size_t grow = this->Queries.empty() ? 64 : this->Queries.size();
    this->Queries.resize(this->Queries.size() + grow);
    glGenQueries(static_cast<GLsizei>(grow), this->Queries.data() + this->NextFree);
  }
  const unsigned int query = this->Queries[this->NextFree++];
  glBeginQuery(GL_SAMPLES_PASSED, query);
  return query;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastOcclusionQueries::End()
{
  glEndQuery(GL_SAMPLES_PASSED);
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastOcclusionQueries::IsAvailable(unsigned int query) const
{
  GLuint available = GL_FALSE;
  glGetQueryObjectuiv(query, GL_QUERY_RESULT_AVAILABLE, &available);
  return available != GL_FALSE;
}

//------------------------------------------------------------------------------
unsigned int vtkTiledRayCastOcclusionQueries::GetResult(unsigned int query) const
{
  GLuint samples = 0;
  glGetQueryObjectuiv(query, GL_QUERY_RESULT, &samples);
  return samples;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastOcclusionQueries::BeginConditionalRender(unsigned int query) const
{
  glBeginConditionalRender(query, GL_QUERY_WAIT);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastOcclusionQueries::EndConditionalRender() const
{
  glEndConditionalRender();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastOcclusionQueries::ReleaseGraphicsResources()
{
  if (!this->Queries.empty())
  {
    glDeleteQueries(static_cast<GLsizei>(this->Queries.size()), this->Queries.data());
  }
  this->Queries.clear();
  this->NextFree = 0;
}
