/*=========================================================================

  Program:   TiledRayCast
  Module:    TiledRayCastMessageCounter.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// trctest::MessageCounter: counts and keeps the errors and warnings an object reports, and keeps
// them out of the test log (whose "ERROR:" text would fail the test). Observe ErrorEvent,
// WarningEvent or both with one counter. Shared by the modules' tests.
#ifndef TiledRayCastMessageCounter_h
#define TiledRayCastMessageCounter_h

#include "vtkCommand.h"

#include <string>

namespace trctest
{
class MessageCounter : public vtkCommand
{
public:
  static MessageCounter* New() { return new MessageCounter; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    ++this->Count;
    this->Text += text;
    if (event == vtkCommand::ErrorEvent)
    {
      ++this->Errors;
      this->LastError = text;
    }
    else
    {
      ++this->Warnings;
      this->LastWarning = text;
    }
  }
  void Clear()
  {
    this->Count = this->Errors = this->Warnings = 0;
    this->Text.clear();
    this->LastError.clear();
    this->LastWarning.clear();
  }
  int Count = 0;    // every message observed
  std::string Text; // all of them, one after the other
  int Errors = 0;
  int Warnings = 0;
  std::string LastError;
  std::string LastWarning;
};
} // namespace trctest

#endif
