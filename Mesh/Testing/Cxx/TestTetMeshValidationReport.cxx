/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTetMeshValidationReport.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The validation report: counts, usability, summary text and copying.
#include "TiledRayCastTestCheck.h"

#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkTetMeshValidationReport.h"

#include <iostream>
#include <sstream>

int TestTetMeshValidationReport(int, char*[])
{
  vtkNew<vtkTetMeshValidationReport> report;
  TRC_CHECK(report->GetUsable());
  TRC_CHECK(!report->HasDefects());

  report->SetNumberOfInputCells(10);
  report->SetNumberOfTetrahedra(14);
  report->SetNumberOfSplitCells(1);
  report->SetNumberOfCrackFaces(6);
  report->GetDegenerateCellIds()->InsertNextValue(3);
  TRC_CHECK(report->HasDefects());
  const std::string summary = report->GetSummary();
  TRC_CHECK(summary.find("14 tetrahedra") != std::string::npos);
  TRC_CHECK(summary.find("6 crack faces") != std::string::npos);
  TRC_CHECK(summary.find("1 non-tetrahedral 3D cells split") != std::string::npos);

  report->SetError("");
  TRC_CHECK(!report->GetUsable());
  TRC_CHECK(std::string(report->GetErrorMessage()).size() > 0);
  report->SetError("no 3D cells");
  TRC_CHECK(report->GetSummary().find("unusable: no 3D cells") == 0);

  vtkNew<vtkTetMeshValidationReport> copy;
  copy->DeepCopy(report);
  TRC_CHECK(!copy->GetUsable());
  TRC_CHECK(copy->GetNumberOfCrackFaces() == 6);
  TRC_CHECK(copy->GetDegenerateCellIds()->GetNumberOfValues() == 1);

  std::ostringstream printed;
  copy->Print(printed);
  TRC_CHECK(printed.str().find("NumberOfCrackFaces: 6") != std::string::npos);

  report->Reset();
  TRC_CHECK(report->GetUsable());
  TRC_CHECK(!report->HasDefects());
  TRC_CHECK(report->GetDegenerateCellIds()->GetNumberOfValues() == 0);
  return EXIT_SUCCESS;
}
