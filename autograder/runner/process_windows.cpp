// stage_process.h on Windows (MinGW-w64 and MSVC).
//
// Confinement of a stage server: a job object, created per server and assigned before the
// server runs its first instruction (created suspended), holds the server and everything it
// starts (a process in a job cannot leave it):
//   - memory: JOB_OBJECT_LIMIT_JOB_MEMORY, the memory committed by all its processes together
//     (an allocation past it fails: std::bad_alloc, "ran out of memory"). The judge also watches
//     that sum itself while it waits for a reply and ends the job when it passes the limit
//     ("memory limit"): Wine accepts the job's limit but does not enforce it, and there each
//     process's count is the memory it wrote to (its resident private memory and swap), not all
//     it committed; so under Wine a stage that writes to its memory is stopped, one that only
//     asks for memory without using it is not (and costs nothing);
//   - processes: JOB_OBJECT_LIMIT_ACTIVE_PROCESS (a fork bomb stops at the limit);
//   - killed with its stage: TerminateJobObject ends every process in the job at once, and
//     JOB_OBJECT_LIMIT_KILL_ON_JOB_CLOSE ends them if the judge itself dies (parent death);
//   - crashes: JOB_OBJECT_LIMIT_DIE_ON_UNHANDLED_EXCEPTION and the inherited error mode end a
//     crashing process at once with its exception code (no Windows Error Reporting dialog),
//     which stop() names (access violation, stack overflow, ...);
//   - output: stdout and stderr go into a pipe that a thread of the judge drains, keeping the
//     first output_limit_bytes (the stage code can never block on a full pipe);
//   - only the three pipe ends are inherited (PROC_THREAD_ATTRIBUTE_HANDLE_LIST).
// What Linux adds and Windows does not have here: a separate user id and Landlock. Stage code
// runs with the student's own rights and could write their files (docs/instructors.md).
#include "stage_process.h"

#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>
// (after windows.h)
#include <psapi.h>

#include <fcntl.h>
#include <io.h>

#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace raylab::grading {
namespace {

constexpr UINT kKilledExitCode = 0xDEAD;  // what TerminateJobObject leaves as the exit code
constexpr UINT kMemoryExitCode = 0xDEAE;  // the same when the judge's memory watch ended the job
constexpr auto kMemoryCheckInterval = std::chrono::milliseconds(50);  // how often the watch looks
// Requests queued for a server that does not read them: past this, send() gives up as if timed out.
constexpr std::size_t kMaxQueuedRequestBytes = std::size_t{64} << 20;

std::string last_error(const char* what) {
  const DWORD code = ::GetLastError();
  char text[512] = {0};
  ::FormatMessageA(FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, nullptr, code, 0, text, sizeof text, nullptr);
  std::string message = std::string(what) + " failed (error " + std::to_string(code) + ")";
  if (text[0] != '\0') message += ": " + std::string(text);
  while (!message.empty() && (message.back() == '\n' || message.back() == '\r' || message.back() == ' ')) message.pop_back();
  return message;
}

// An exception code that ended a process, named for a student.
Message exception_description(DWORD code) {
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%08lX", static_cast<unsigned long>(code));
  std::vector<Message> detail;
  switch (code) {
    case 0xC0000005: detail.push_back(MessageId::crash_access_violation); break;
    case 0xC00000FD: detail.push_back(MessageId::crash_stack_overflow); break;
    case 0xC0000094: detail.push_back(MessageId::crash_integer_division); break;
    case 0xC000008C: detail.push_back(MessageId::crash_array_bounds); break;
    case 0xC000001D: detail.push_back(MessageId::crash_illegal_instruction); break;
    case 0xC0000017: case 0xC000012D: detail.push_back(MessageId::crash_out_of_memory); break;
    case 0xC0000374: detail.push_back(MessageId::crash_heap_corruption); break;
    case 0xC0000409: detail.push_back(MessageId::crash_stack_buffer_overrun); break;
    case 0xC0000420: detail.push_back(MessageId::crash_assertion_failure); break;
    default: break;
  }
  return {MessageId::crash_exception, {{"code", hex}, {"detail", detail}}};
}

// A pipe of which the child gets one end (inheritable) and the judge keeps the other (not).
struct Pipe {
  HANDLE read = nullptr, write = nullptr;
};
Pipe make_pipe() {
  SECURITY_ATTRIBUTES attributes{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
  Pipe pipe;
  if (!::CreatePipe(&pipe.read, &pipe.write, &attributes, 0)) throw std::runtime_error(last_error("CreatePipe"));
  return pipe;
}
void keep_private(HANDLE handle) { ::SetHandleInformation(handle, HANDLE_FLAG_INHERIT, 0); }
void close_handle(HANDLE& handle) {
  if (handle != nullptr && handle != INVALID_HANDLE_VALUE) ::CloseHandle(handle);
  handle = nullptr;
}

// Quotes one command-line argument the way CommandLineToArgvW and the C runtimes parse it.
std::string quoted(const std::string& argument) {
  std::string text = "\"";
  std::size_t backslashes = 0;
  for (const char c : argument) {
    if (c == '\\') {
      ++backslashes;
      continue;
    }
    text.append(c == '"' ? 2 * backslashes + 1 : backslashes, '\\');
    backslashes = 0;
    text += c;
  }
  text.append(2 * backslashes, '\\');
  return text + "\"";
}

// The memory committed by all processes in `job` together, as JOB_OBJECT_LIMIT_JOB_MEMORY counts
// it on Windows (each process's PagefileUsage, its private committed memory; under Wine, what
// it wrote to). A process that ends between the list and the look is not counted.
std::uint64_t job_memory_bytes(HANDLE job, std::size_t max_processes) {
  std::vector<ULONG_PTR> storage(2 + std::max<std::size_t>(max_processes, 64));  // header + ids
  auto* list = reinterpret_cast<JOBOBJECT_BASIC_PROCESS_ID_LIST*>(storage.data());
  const DWORD size = static_cast<DWORD>(storage.size() * sizeof(ULONG_PTR));
  // ERROR_MORE_DATA still fills the list as far as it goes: those processes are counted.
  if (!::QueryInformationJobObject(job, JobObjectBasicProcessIdList, list, size, nullptr) && ::GetLastError() != ERROR_MORE_DATA)
    return 0;
  std::uint64_t total = 0;
  for (DWORD i = 0; i < list->NumberOfProcessIdsInList; ++i) {
    const HANDLE process = ::OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, FALSE, static_cast<DWORD>(list->ProcessIdList[i]));
    if (process == nullptr) continue;
    PROCESS_MEMORY_COUNTERS counters{};
    counters.cb = sizeof counters;
    if (::GetProcessMemoryInfo(process, &counters, sizeof counters)) total += counters.PagefileUsage;
    ::CloseHandle(process);
  }
  return total;
}

}  // namespace

struct StageProcess::Child {
  HANDLE process = nullptr, job = nullptr;
  std::thread output_reader;  // drains the output pipe into `output`
  std::mutex mutex;
  std::string output;
  // Anonymous pipes cannot be waited on with a time-out, and polling them loads Wine's server.
  // So a thread copies the server's replies into a pipe of the judge's own (whose read end is
  // reply_fd) and counts what it delivered: wait_for_reply waits for that count to change.
  std::thread reply_pump;
  HANDLE reply_local_write = nullptr;
  std::condition_variable delivered_changed;
  std::uint64_t delivered = 0;  // chunks copied, under `mutex`
  bool reply_ended = false;     // the server's reply pipe reached its end, under `mutex`
  // Requests go the other way through a thread too, so that the judge never blocks in a write to
  // a server that stopped reading: send() queues a frame, request_pump writes it. Under `mutex`:
  std::thread request_pump;
  HANDLE request_write = nullptr;  // the judge's end of the server's request pipe (the pump's)
  std::deque<std::string> queued_requests;
  std::size_t queued_bytes = 0;
  bool requests_closed = false;  // stop(): the pump closes the pipe once the queue is empty
  bool request_failed = false;   // a write failed: the server is gone
  std::condition_variable request_queued;
  // The judge's own memory watch (see the top of this file); used by the judge's thread only.
  std::uint64_t memory_limit_bytes = 0;  // 0: none
  std::size_t max_processes = 0;
  long memory_limit_mb = 0;
  Clock::time_point next_memory_check{};
  bool over_memory = false;  // the watch ended the job

  // Looks at the job's memory if it is time to; ends the job when it is over the limit. True once
  // it has done so.
  bool check_memory() {
    if (over_memory || memory_limit_bytes == 0) return over_memory;
    const auto now = Clock::now();
    if (now < next_memory_check) return false;
    next_memory_check = now + kMemoryCheckInterval;
    if (job_memory_bytes(job, max_processes) <= memory_limit_bytes) return false;
    over_memory = true;
    ::TerminateJobObject(job, kMemoryExitCode);
    return true;
  }
};

namespace {
bool judge_in_own_job = false;  // limit_judge_memory put it there: stage servers break away from it
}  // namespace

// A job object of the judge's own whose limit is each process's committed memory. Stage servers
// break away from it into their own jobs (JOB_OBJECT_LIMIT_BREAKAWAY_OK), so that, as on Linux, a
// stage may be given more than the judge. Where the judge cannot join a job (in one already, on
// Windows before 8), it goes on without the limit.
void limit_judge_memory(long megabytes) {
  if (megabytes <= 0) return;
  HANDLE job = ::CreateJobObjectA(nullptr, nullptr);
  if (job == nullptr) return;
  JOBOBJECT_EXTENDED_LIMIT_INFORMATION limits{};
  limits.BasicLimitInformation.LimitFlags = JOB_OBJECT_LIMIT_PROCESS_MEMORY | JOB_OBJECT_LIMIT_BREAKAWAY_OK;
  limits.ProcessMemoryLimit = static_cast<SIZE_T>(megabytes) << 20;
  if (::SetInformationJobObject(job, JobObjectExtendedLimitInformation, &limits, sizeof limits) &&
      ::AssignProcessToJobObject(job, ::GetCurrentProcess())) {
    judge_in_own_job = true;  // (its handle stays open as long as the judge runs)
    return;
  }
  ::CloseHandle(job);
}

void prepare_judge() {
  // Inherited by every stage server: no dialog box for a crash or a missing drive; the process
  // just ends with its exception code.
  ::SetErrorMode(SEM_FAILCRITICALERRORS | SEM_NOGPFAULTERRORBOX | SEM_NOOPENFILEERRORBOX);
}

std::string default_stage_server_path() {
  char path[MAX_PATH * 4];
  const DWORD length = ::GetModuleFileNameA(nullptr, path, sizeof path);
  if (length == 0 || length >= sizeof path) throw std::runtime_error(last_error("GetModuleFileName"));
  std::string program(path, length);
  const std::size_t dot = program.size() >= 4 ? program.size() - 4 : 0;
  if (_stricmp(program.c_str() + dot, ".exe") == 0) program.erase(dot);
  return program + "-stage-server.exe";
}

Message sandbox_description() { return MessageId::sandbox_windows_job; }

int stage_cgroup_version() { return 0; }

StageProcess::StageProcess() = default;

bool StageProcess::running() const { return child_ != nullptr; }

StageProcess::~StageProcess() {
  if (running()) {
    std::string ignored;
    stop(true, ignored);
  }
}

void StageProcess::start(const std::string& program, const SandboxLimits& limits) {
  auto child = std::make_unique<Child>();
  Pipe requests = make_pipe(), replies = make_pipe(), output = make_pipe();
  keep_private(requests.write);
  keep_private(replies.read);
  keep_private(output.read);
  SECURITY_ATTRIBUTES inheritable{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
  HANDLE null_input = ::CreateFileA("NUL", GENERIC_READ, FILE_SHARE_READ | FILE_SHARE_WRITE, &inheritable, OPEN_EXISTING, 0, nullptr);
  auto close_all = [&]() {
    for (HANDLE* handle : {&requests.read, &requests.write, &replies.read, &replies.write, &output.read, &output.write, &null_input})
      close_handle(*handle);
  };
  auto fail = [&](const char* what) {
    const std::string message = last_error(what);
    close_all();
    close_handle(child->process);
    close_handle(child->job);
    throw std::runtime_error(message);
  };
  if (null_input == INVALID_HANDLE_VALUE) fail("opening NUL");

  child->job = ::CreateJobObjectA(nullptr, nullptr);
  if (child->job == nullptr) fail("CreateJobObject");
  JOBOBJECT_EXTENDED_LIMIT_INFORMATION job_limits{};
  job_limits.BasicLimitInformation.LimitFlags = JOB_OBJECT_LIMIT_KILL_ON_JOB_CLOSE | JOB_OBJECT_LIMIT_DIE_ON_UNHANDLED_EXCEPTION;
  if (limits.max_processes > 0) {
    job_limits.BasicLimitInformation.LimitFlags |= JOB_OBJECT_LIMIT_ACTIVE_PROCESS;
    job_limits.BasicLimitInformation.ActiveProcessLimit = static_cast<DWORD>(limits.max_processes);
  }
  if (limits.memory_limit_mb > 0) {
    job_limits.BasicLimitInformation.LimitFlags |= JOB_OBJECT_LIMIT_JOB_MEMORY;
    job_limits.JobMemoryLimit = static_cast<SIZE_T>(limits.memory_limit_mb) * 1024 * 1024;
  }
  if (!::SetInformationJobObject(child->job, JobObjectExtendedLimitInformation, &job_limits, sizeof job_limits))
    fail("SetInformationJobObject");
  child->memory_limit_bytes = static_cast<std::uint64_t>(std::max(limits.memory_limit_mb, 0L)) * 1024 * 1024;
  child->memory_limit_mb = limits.memory_limit_mb;
  child->max_processes = static_cast<std::size_t>(std::max(limits.max_processes, 0));

  // Only the child's three pipe ends and NUL are inherited, whatever else the judge has open.
  HANDLE inherited[] = {requests.read, replies.write, output.write, null_input};
  SIZE_T attribute_size = 0;
  ::InitializeProcThreadAttributeList(nullptr, 1, 0, &attribute_size);
  std::vector<char> attribute_storage(attribute_size);
  auto* attributes = reinterpret_cast<LPPROC_THREAD_ATTRIBUTE_LIST>(attribute_storage.data());
  if (!::InitializeProcThreadAttributeList(attributes, 1, 0, &attribute_size)) fail("InitializeProcThreadAttributeList");
  if (!::UpdateProcThreadAttribute(attributes, 0, PROC_THREAD_ATTRIBUTE_HANDLE_LIST, inherited, sizeof inherited, nullptr, nullptr))
    fail("UpdateProcThreadAttribute");

  STARTUPINFOEXA startup{};
  startup.StartupInfo.cb = sizeof startup;
  startup.StartupInfo.dwFlags = STARTF_USESTDHANDLES;
  startup.StartupInfo.hStdInput = null_input;
  startup.StartupInfo.hStdOutput = output.write;
  startup.StartupInfo.hStdError = output.write;
  startup.lpAttributeList = attributes;
  // The server's arguments: the handle values of its request and reply pipes (protocol.cpp).
  std::string command = quoted(program) + " " + std::to_string(reinterpret_cast<std::uintptr_t>(requests.read)) + " " +
                        std::to_string(reinterpret_cast<std::uintptr_t>(replies.write));
  PROCESS_INFORMATION info{};
  const DWORD flags = CREATE_SUSPENDED | CREATE_NO_WINDOW | EXTENDED_STARTUPINFO_PRESENT;
  BOOL created = ::CreateProcessA(program.c_str(), command.data(), nullptr, nullptr, TRUE,
                                  flags | (judge_in_own_job ? CREATE_BREAKAWAY_FROM_JOB : 0), nullptr, nullptr,
                                  &startup.StartupInfo, &info);
  if (!created && judge_in_own_job && ::GetLastError() == ERROR_ACCESS_DENIED)  // a job around the judge's forbids it
    created = ::CreateProcessA(program.c_str(), command.data(), nullptr, nullptr, TRUE, flags, nullptr, nullptr,
                               &startup.StartupInfo, &info);
  ::DeleteProcThreadAttributeList(attributes);
  if (!created) fail(("starting " + program).c_str());
  child->process = info.hProcess;
  if (!::AssignProcessToJobObject(child->job, info.hProcess)) {
    ::TerminateProcess(info.hProcess, kKilledExitCode);
    ::CloseHandle(info.hThread);
    fail("AssignProcessToJobObject");
  }
  ::ResumeThread(info.hThread);
  ::CloseHandle(info.hThread);
  // The child's ends are the child's now; the judge's copies go, so that the pipes end when it does.
  close_handle(requests.read);
  close_handle(replies.write);
  close_handle(output.write);
  close_handle(null_input);

  // Drains the output pipe (the stage code never blocks on it), keeping the first bytes.
  const auto limit = static_cast<std::size_t>(limits.output_limit_bytes);
  child->output_reader = std::thread([output_read = output.read, limit, raw = child.get()]() {
    char buffer[65536];
    DWORD got = 0;
    while (::ReadFile(output_read, buffer, sizeof buffer, &got, nullptr) && got > 0) {
      const std::lock_guard<std::mutex> lock(raw->mutex);
      if (raw->output.size() < limit) raw->output.append(buffer, std::min<std::size_t>(got, limit - raw->output.size()));
    }
    ::CloseHandle(output_read);
  });

  // The replies, copied into the judge's own pipe (see Child::reply_pump).
  SECURITY_ATTRIBUTES private_pipe{sizeof(SECURITY_ATTRIBUTES), nullptr, FALSE};
  HANDLE local_read = nullptr;
  if (!::CreatePipe(&local_read, &child->reply_local_write, &private_pipe, 1 << 20)) local_read = nullptr;
  if (local_read != nullptr)
    child->reply_pump = std::thread([server_replies = replies.read, raw = child.get()]() {
      std::vector<char> buffer(1 << 16);
      DWORD got = 0;
      while (::ReadFile(server_replies, buffer.data(), static_cast<DWORD>(buffer.size()), &got, nullptr) && got > 0) {
        DWORD done = 0, wrote = 0;
        for (; done < got; done += wrote)
          if (!::WriteFile(raw->reply_local_write, buffer.data() + done, got - done, &wrote, nullptr)) break;
        if (done < got) break;  // the judge closed its end: it wants no more replies
        const std::lock_guard<std::mutex> lock(raw->mutex);
        ++raw->delivered;
        raw->delivered_changed.notify_all();
      }
      ::CloseHandle(server_replies);
      ::CloseHandle(raw->reply_local_write);  // the judge's reads see the end of file
      const std::lock_guard<std::mutex> lock(raw->mutex);
      raw->reply_ended = true;
      raw->delivered_changed.notify_all();
    });
  else
    close_handle(replies.read);
  // The requests, written by a thread of their own (see Child::request_pump).
  child->request_write = requests.write;
  requests.write = nullptr;
  child->request_pump = std::thread([raw = child.get()]() {
    for (;;) {
      std::unique_lock<std::mutex> lock(raw->mutex);
      raw->request_queued.wait(lock, [&]() { return !raw->queued_requests.empty() || raw->requests_closed; });
      if (raw->queued_requests.empty()) break;  // closed, and all is written
      const std::string frame = std::move(raw->queued_requests.front());
      raw->queued_requests.pop_front();
      raw->queued_bytes -= frame.size();
      lock.unlock();
      DWORD done = 0, wrote = 0;
      for (; done < frame.size(); done += wrote)
        if (!::WriteFile(raw->request_write, frame.data() + done, static_cast<DWORD>(frame.size() - done), &wrote, nullptr)) break;
      if (done < frame.size()) {  // the server is gone
        const std::lock_guard<std::mutex> failed(raw->mutex);
        raw->request_failed = true;
        break;
      }
    }
    ::CloseHandle(raw->request_write);  // a server waiting for requests sees end of file and exits
  });
  reply_fd_ = local_read != nullptr ? ::_open_osfhandle(reinterpret_cast<std::intptr_t>(local_read), _O_RDONLY | _O_BINARY) : -1;
  child_ = std::move(child);
  if (reply_fd_ < 0) {
    std::string ignored;
    stop(true, ignored);
    throw std::runtime_error("_open_osfhandle failed for the stage server's pipes");
  }
}

bool StageProcess::send(const std::string& payload, Clock::time_point) {
  Child& child = *child_;
  std::string frame = protocol::framed(payload);
  const std::lock_guard<std::mutex> lock(child.mutex);
  if (child.request_failed) throw std::system_error(EPIPE, std::generic_category(), "write");
  // The pump writes it; the deadline holds while the judge waits for the reply. A server that
  // reads nothing while asking and asking (callbacks) fills the queue: then it has stopped reading.
  if (child.queued_bytes + frame.size() > kMaxQueuedRequestBytes) return false;
  child.queued_bytes += frame.size();
  child.queued_requests.push_back(std::move(frame));
  child.request_queued.notify_all();
  return true;
}

protocol::FrameRead StageProcess::receive(std::string& payload, std::uint32_t max_bytes, Clock::time_point deadline) {
  return protocol::read_frame(reply_fd_, payload, max_bytes, [&]() { return wait_for_reply(deadline); });
}

bool StageProcess::wait_for_reply(Clock::time_point deadline) const {
  Child& child = *child_;
  // Waits in steps of the memory watch's interval, looking at the job's memory between them.
  for (;;) {
    // Over the memory limit: the job is ended, and the read sees the end of the replies.
    if (child.check_memory()) return true;
    std::unique_lock<std::mutex> lock(child.mutex);
    const std::uint64_t before = child.delivered;
    if (child.reply_ended) return true;  // the read reports the end (or what is left)
    lock.unlock();
    // Bytes delivered earlier and not read yet (one look; the pump tells of anything new).
    DWORD available = 0;
    const auto pipe = reinterpret_cast<HANDLE>(::_get_osfhandle(reply_fd_));
    if (!::PeekNamedPipe(pipe, nullptr, 0, nullptr, &available, nullptr) || available > 0) return true;
    lock.lock();
    const Clock::time_point until =
        child.memory_limit_bytes == 0 ? deadline : std::min(deadline, Clock::now() + kMemoryCheckInterval);
    if (child.delivered_changed.wait_until(lock, until, [&]() { return child.delivered != before || child.reply_ended; }))
      return true;
    if (Clock::now() >= deadline) return false;
  }
}

ProcessEnd StageProcess::stop(bool kill_now, std::string& output) {
  ProcessEnd end;
  if (!child_) return end;
  {  // the pump closes the request pipe after what is queued: a server waiting for requests exits
    const std::lock_guard<std::mutex> lock(child_->mutex);
    child_->requests_closed = true;
    if (kill_now) child_->queued_requests.clear();
    child_->request_queued.notify_all();
  }
  if (!kill_now) ::WaitForSingleObject(child_->process, 500);
  ::TerminateJobObject(child_->job, kKilledExitCode);  // the server, if still there, and all it started
  ::WaitForSingleObject(child_->process, INFINITE);
  // TerminateJobObject is asynchronous for the other processes: wait until the job is empty.
  for (int i = 0; i < 10000; ++i) {
    JOBOBJECT_BASIC_ACCOUNTING_INFORMATION accounting{};
    if (!::QueryInformationJobObject(child_->job, JobObjectBasicAccountingInformation, &accounting, sizeof accounting, nullptr) ||
        accounting.ActiveProcesses == 0)
      break;
    ::Sleep(1);
  }
  DWORD code = 0;
  ::GetExitCodeProcess(child_->process, &code);
  if (code == kMemoryExitCode || child_->over_memory) {
    end.crashed = true;
    end.crash = {MessageId::crash_memory_limit, {{"limit", std::to_string(child_->memory_limit_mb)}}};
  } else if (code == kKilledExitCode) {
    end.crashed = true;
    end.crash = MessageId::crash_killed;
  } else if (code == 3) {  // what abort() leaves with the MinGW and MSVC runtimes
    end.crashed = true;
    end.crash = MessageId::crash_abort_status_3;
  } else if (code >= 0xC0000000u) {
    end.crashed = true;
    end.crash = exception_description(code);
  } else {
    end.exit_code = static_cast<int>(code);
  }
  if (reply_fd_ >= 0) ::_close(reply_fd_);  // a pump blocked on a full pipe of ours stops
  if (child_->reply_pump.joinable()) child_->reply_pump.join();      // the server's end is gone: end of file
  if (child_->request_pump.joinable()) child_->request_pump.join();  // its write fails or its queue is empty
  if (child_->output_reader.joinable()) child_->output_reader.join();  // every writer is gone: end of file
  output += child_->output;
  close_handle(child_->process);
  close_handle(child_->job);
  child_.reset();
  request_fd_ = reply_fd_ = -1;
  return end;
}

}  // namespace raylab::grading
