/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastIntegrationTextures.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastIntegrationTextures.h"

#include "vtkObject.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTiledRayCastPreIntegrationTable.h"
#include "vtkTiledRayCastTransferFunction.h"
#include "vtkTiledRayCastVolumeMapper.h"
#include "vtkUnstructuredGridPartialPreIntegration.h"
#include "vtk_glew.h"

#include <vector>

//------------------------------------------------------------------------------
vtkTiledRayCastIntegrationTextures::vtkTiledRayCastIntegrationTextures() = default;

//------------------------------------------------------------------------------
vtkTiledRayCastIntegrationTextures::~vtkTiledRayCastIntegrationTextures() = default;

//------------------------------------------------------------------------------
void vtkTiledRayCastIntegrationTextures::UpdateNodes(vtkOpenGLRenderWindow* window,
  vtkTiledRayCastTransferFunction* transferFunction, vtkIdType& uploaded)
{
  if (transferFunction->GetMTime() > this->UploadedNodesTime)
  {
    const std::vector<float>& texels = transferFunction->GetNodeTexels();
    this->NodeBuffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
    this->NodeBuffer->Upload(texels, vtkOpenGLBufferObject::TextureBuffer);
    this->NodeTexture->SetContext(window);
    this->NodeTexture->SetInternalFormat(GL_RGBA32F);
    this->NodeTexture->CreateTextureBuffer(
      static_cast<unsigned int>(texels.size() / 4), 4, VTK_FLOAT, this->NodeBuffer);
    this->UploadedNodesTime = transferFunction->GetMTime();
    uploaded += static_cast<vtkIdType>(texels.size() * sizeof(float));
  }
  if (!this->PsiTexture->GetHandle())
  {
    // Moreland and Angel's Psi: the same static table as VTK's partial pre-integration.
    vtkUnstructuredGridPartialPreIntegration::BuildPsiTable();
    int size = 0;
    float* psi = vtkUnstructuredGridPartialPreIntegration::GetPsiTable(size);
    this->PsiTexture->SetContext(window);
    this->PsiTexture->SetInternalFormat(GL_R32F);
    this->PsiTexture->SetFormat(GL_RED);
    this->PsiTexture->SetDataType(GL_FLOAT);
    this->PsiTexture->SetMinificationFilter(vtkTextureObject::Linear);
    this->PsiTexture->SetMagnificationFilter(vtkTextureObject::Linear);
    this->PsiTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    this->PsiTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    // The table is indexed [front][back]; texture rows are t, columns s: s = back, t = front.
    this->PsiTexture->Create2DFromRaw(size, size, 1, VTK_FLOAT, psi);
    uploaded += static_cast<vtkIdType>(size) * size * 4;
  }
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastIntegrationTextures::UpdateTable(vtkOpenGLRenderWindow* window,
  vtkTiledRayCastPreIntegrationTable* table, int mode, vtkIdType& uploaded, std::string& error)
{
  if (table == this->UploadedTable && table->GetMTime() <= this->UploadedTableTime &&
    mode == this->UploadedTableMode)
  {
    return true;
  }
  int size[3];
  table->GetSize(size);
  vtkTextureObject* tex = this->TableTexture;
  tex->ReleaseGraphicsResources(window);
  tex->SetContext(window);
  tex->SetInternalFormat(GL_RGBA32F);
  tex->SetFormat(GL_RGBA);
  tex->SetDataType(GL_FLOAT);
  tex->SetMinificationFilter(vtkTextureObject::Linear);
  tex->SetMagnificationFilter(vtkTextureObject::Linear);
  tex->SetWrapS(vtkTextureObject::ClampToEdge);
  tex->SetWrapT(vtkTextureObject::ClampToEdge);
  tex->SetWrapR(vtkTextureObject::ClampToEdge);
  float* data = table->GetTable();
  bool ok = table->GetDimension() == 3
    ? tex->Create3DFromRaw(size[0], size[1], size[2], 4, VTK_FLOAT, data)
    : tex->Create2DFromRaw(size[0], size[1], 4, VTK_FLOAT, data);
  if (!ok)
  {
    error = "Cannot create the pre-integration table texture. Nothing is drawn.";
    return false;
  }
  this->UploadedTableTime = table->GetMTime();
  this->UploadedTable = table;
  this->UploadedTableMode = mode;
  uploaded += table->GetNumberOfBytes();
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastIntegrationTextures::ActivateTextures(int mode, bool activate, bool psi)
{
  std::vector<vtkTextureObject*> textures;
  if (mode == vtkTiledRayCastVolumeMapper::PARTIAL_PRE_INTEGRATION)
  {
    textures.push_back(this->NodeTexture);
    if (psi)
    {
      textures.push_back(this->PsiTexture);
    }
  }
  else
  {
    textures.push_back(this->TableTexture);
  }
  for (vtkTextureObject* t : textures)
  {
    if (activate)
    {
      t->Activate();
    }
    else
    {
      t->Deactivate();
    }
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastIntegrationTextures::SetUniforms(vtkShaderProgram* p, int mode,
  vtkTiledRayCastTransferFunction* transferFunction, vtkTiledRayCastPreIntegrationTable* table,
  double scalarShift, double scalarScale)
{
  if (mode == vtkTiledRayCastVolumeMapper::PARTIAL_PRE_INTEGRATION)
  {
    p->SetUniformi("in_transferFunction", this->NodeTexture->GetTextureUnit());
    p->SetUniformi("in_transferFunctionNodes", transferFunction->GetNumberOfNodes());
    p->SetUniformi("in_psiTable", this->PsiTexture->GetTextureUnit());
    p->SetUniformf("in_psiTableSize", static_cast<float>(this->PsiTexture->GetWidth()));
    return;
  }
  int size[3];
  table->GetSize(size);
  double range[2];
  table->GetScalarRange(range);
  // The mesh's scalars are shifted and scaled on the GPU (vtkTetMesh::GetScalarShift,
  // GetScalarScale): so are the table's first grid scalar and its spacing.
  const float scalarMap[3] = { static_cast<float>((range[0] - scalarShift) * scalarScale),
    static_cast<float>(
      range[1] > range[0] ? (size[0] - 1) / ((range[1] - range[0]) * scalarScale) : 0.0),
    static_cast<float>(size[0]) };
  p->SetUniformi("in_preIntegrationTable", this->TableTexture->GetTextureUnit());
  p->SetUniform3f("in_tableScalarMap", scalarMap);
  if (mode == vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_3D)
  {
    const double longest = table->GetMaximumLength();
    const float lengthMap[3] = { static_cast<float>(longest > 0 ? (size[2] - 1) / longest : 0.0),
      static_cast<float>(size[2]), static_cast<float>(longest > 0 ? longest : 1e30) };
    p->SetUniform3f("in_tableLengthMap", lengthMap);
  }
  else
  {
    p->SetUniformf("in_tableReferenceLength", static_cast<float>(table->GetReferenceLength()));
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastIntegrationTextures::ReleaseGraphicsResources(vtkWindow* window)
{
  this->NodeTexture->ReleaseGraphicsResources(window);
  this->NodeBuffer->ReleaseGraphicsResources();
  this->PsiTexture->ReleaseGraphicsResources(window);
  this->TableTexture->ReleaseGraphicsResources(window);
  this->UploadedNodesTime = 0;
  this->UploadedTableTime = 0;
  this->UploadedTable = nullptr;
  this->UploadedTableMode = -1;
}
