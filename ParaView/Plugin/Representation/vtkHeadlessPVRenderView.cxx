/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessPVRenderView.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkHeadlessPVRenderView.h"

#include "vtkCLIOptions.h"
#include "vtkHeadlessEGLRenderWindow.h"
#include "vtkHeadlessObjectFactory.h"
#include "vtkHeadlessSharedWindowInitializer.h"
#include "vtkLogger.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPVProcessWindow.h"
#include "vtkProcessModule.h"
#include "vtkRemotingCoreConfiguration.h"

#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

#ifdef __linux__
#include <sched.h>
#endif

namespace
{
// How many cores this process may run on (its CPU affinity), or 0 where that is not known.
int AllowedCores()
{
#ifdef __linux__
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0)
  {
    return CPU_COUNT(&set);
  }
#endif
  return 0;
}

// A non-negative integer, or -1.
int ParseIndex(const char* text)
{
  if (!text || !*text)
  {
    return -1;
  }
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  return (*end == '\0' && value >= 0 && value < 1 << 20) ? static_cast<int>(value) : -1;
}

// This process's rank among those of the MPI job on its machine, as the launcher tells it (Open
// MPI, MPICH and Intel MPI, Slurm, PMI), or its rank in the job when none does.
int LocalRank()
{
  for (const char* name :
    { "OMPI_COMM_WORLD_LOCAL_RANK", "MPI_LOCALRANKID", "SLURM_LOCALID", "PMI_LOCAL_RANK" })
  {
    const int rank = ParseIndex(std::getenv(name));
    if (rank >= 0)
    {
      return rank;
    }
  }
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return controller ? controller->GetLocalProcessId() : 0;
}
}

vtkStandardNewMacro(vtkHeadlessPVRenderView);

//------------------------------------------------------------------------------
void vtkHeadlessPVRenderView::InitializeProcess()
{
  vtkProcessModule* processModule = vtkProcessModule::GetProcessModule();
  if (!processModule)
  {
    return;
  }
  const vtkProcessModule::ProcessTypes type = processModule->GetProcessType();
  if (type != vtkProcessModule::PROCESS_SERVER && type != vtkProcessModule::PROCESS_BATCH &&
    type != vtkProcessModule::PROCESS_RENDER_SERVER)
  {
    return;
  }
  vtkRemotingCoreConfiguration* config = vtkRemotingCoreConfiguration::GetInstance();
  const bool eglDevices = ParseIndex(config->GetDisplay().c_str()) >= 0;
  const bool egl = std::strcmp(vtkHeadlessObjectFactory::GetResolvedWindowClassName(),
                     "vtkHeadlessEGLRenderWindow") == 0;
  if (config->GetDisableXDisplayTests() || !(egl || eglDevices))
  {
    return;
  }
  // The option is ParaView's own, parsed by ParaView's own parser into its configuration.
  vtkNew<vtkCLIOptions> options;
  config->PopulateRenderingOptions(options, type);
  std::string program = "pvbatch";
  std::string flag = "--disable-xdisplay-test";
  char* arguments[] = { &program[0], &flag[0], nullptr };
  int count = 2;
  char** argv = arguments;
  if (!options->Parse(count, argv) || !config->GetDisableXDisplayTests())
  {
    vtkGenericWarningMacro("Could not tell ParaView that this process renders with EGL: pass "
                           "--disable-xdisplay-test to pvbatch or pvserver ("
      << options->GetLastErrorMessage() << ")");
  }
}

//------------------------------------------------------------------------------
vtkHeadlessPVRenderView::vtkHeadlessPVRenderView() = default;

//------------------------------------------------------------------------------
vtkHeadlessPVRenderView::~vtkHeadlessPVRenderView() = default;

//------------------------------------------------------------------------------
void vtkHeadlessPVRenderView::StillRender()
{
  this->SetUpHeadlessWindow();
  this->Superclass::StillRender();
}

//------------------------------------------------------------------------------
void vtkHeadlessPVRenderView::InteractiveRender()
{
  this->SetUpHeadlessWindow();
  this->Superclass::InteractiveRender();
}

//------------------------------------------------------------------------------
void vtkHeadlessPVRenderView::SetUpHeadlessWindow()
{
  if (this->HeadlessWindowChecked)
  {
    return;
  }
  this->HeadlessWindowChecked = true;
  // Only server and batch processes have a process window (a client's is null); only the
  // plugin's factory makes it an EGL one.
  auto* processWindow =
    vtkHeadlessEGLRenderWindow::SafeDownCast(vtkPVProcessWindow::GetRenderWindow());
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(this->GetRenderWindow());
  if (!processWindow || !window || window == processWindow ||
    vtkHeadlessSharedWindowInitializer::IsInitialized(window))
  {
    return;
  }
  if (!processWindow->HasContext())
  {
    this->ChooseDevice(processWindow);
  }
  // ParaView's own first render of the view would do this: the process window renders once,
  // which creates its context.
  vtkPVProcessWindow::PrepareForRendering();
  if (!processWindow->HasContext())
  {
    vtkErrorMacro("This process cannot render: it has no X display and no EGL context ("
      << processWindow->GetInitializationError() << ")");
    return;
  }
  std::string error;
  if (!vtkHeadlessSharedWindowInitializer::Initialize(window, processWindow, error))
  {
    vtkErrorMacro("The view's window cannot render on the EGL context: " << error);
    return;
  }
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int rank = controller ? controller->GetLocalProcessId() : 0;
  const std::string platform = processWindow->GetPlatformInUse();
  vtkLogF(INFO, "rank %d renders with EGL on %s %d (%s): %s, OpenGL %s", rank, platform.c_str(),
    processWindow->GetDeviceIndexInUse(), this->DeviceChoice.c_str(),
    processWindow->GetGLRenderer(), processWindow->GetGLVersion());
  const int gpus = vtkHeadlessEGLRenderWindow::GetNumberOfGPUDevices();
  if (platform != "device" && gpus > 0)
  {
    vtkWarningMacro("Rank " << rank << " renders on the CPU (" << processWindow->GetGLRenderer()
                            << ") although this machine has " << gpus << " EGL GPU device(s): "
                            << vtkHeadlessEGLRenderWindow::GetDeviceDescriptions());
  }
  const int cores = AllowedCores();
  if (platform == "device" && cores == 1 && std::thread::hardware_concurrency() > 1)
  {
    // Open MPI binds each rank to one core when there are two ranks or fewer: the GPU driver's
    // threads then share it with Python and IceT, and frames stall (on an H100, 2 ranks:
    // 113 ms a frame bound, 13 ms not; docs/parallel.md).
    vtkWarningMacro("Rank " << rank << " renders on a GPU but may run on one core only "
                            << "(bound by mpirun?): frames stall. Start mpirun with "
                            << "--bind-to none.");
  }
}

//------------------------------------------------------------------------------
void vtkHeadlessPVRenderView::ChooseDevice(vtkHeadlessEGLRenderWindow* processWindow)
{
  const int devices = processWindow->GetNumberOfDevices();
  const int gpus = vtkHeadlessEGLRenderWindow::GetNumberOfGPUDevices();
  int index = -1;
  // ParaView's --displays: ParaView assigns them to ranks (and has set DISPLAY to the value,
  // which is no X display: the plugin's factory then chose EGL).
  const int display = ParseIndex(vtkRemotingCoreConfiguration::GetInstance()->GetDisplay().c_str());
  const char* environment = std::getenv("VTK_DEFAULT_EGL_DEVICE_INDEX");
  if (display >= 0)
  {
    index = display;
    this->DeviceChoice = "--displays";
  }
  else if (environment && *environment)
  {
    // The window itself tries it first, and warns when it does not work.
    this->DeviceChoice = std::string("VTK_DEFAULT_EGL_DEVICE_INDEX=") + environment;
  }
  else if (gpus > 0)
  {
    const int local = LocalRank();
    index = vtkHeadlessEGLRenderWindow::GetGPUDeviceIndex(local % gpus);
    this->DeviceChoice =
      "local rank " + std::to_string(local) + " of " + std::to_string(gpus) + " GPU(s)";
  }
  else
  {
    this->DeviceChoice = "automatic, no EGL GPU device";
  }
  if (index >= devices)
  {
    vtkWarningMacro("EGL device " << index << " (" << this->DeviceChoice << ") does not exist: "
                                  << devices << " EGL device(s); choosing automatically");
    index = -1;
    this->DeviceChoice += ", out of range: automatic";
  }
  this->RequestedDeviceIndex = index;
  if (index >= 0)
  {
    processWindow->SetDeviceIndex(index);
  }
}

//------------------------------------------------------------------------------
void vtkHeadlessPVRenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RequestedDeviceIndex: " << this->RequestedDeviceIndex << "\n";
  os << indent << "DeviceChoice: " << this->DeviceChoice << "\n";
}
