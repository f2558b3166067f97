#include "lsp/lsp_client.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "test_paths.hpp"
#include "time_scale.hpp"

extern char** environ;

namespace edsc::lsp_test {

namespace {

using clock = std::chrono::steady_clock;

// Byte offset of a UTF-16 position in `text` (test-side, written apart from
// the server's line_index on purpose).
std::size_t offset_of(const std::string& text, const json& pos) {
  std::size_t line = pos.at("line"), character = pos.at("character");
  std::size_t i = 0;
  while (line > 0 && i < text.size()) {
    if (text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))) --line;
    ++i;
  }
  std::size_t units = 0;
  while (i < text.size() && units < character && text[i] != '\n' && text[i] != '\r') {
    const auto b = static_cast<unsigned char>(text[i]);
    const std::size_t len = b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : b >= 0xC0 ? 2 : 1;
    units += len == 4 ? 2 : 1;
    i += len;
  }
  return i;
}

}  // namespace

int lsp_process::pipe_capacity(bool to) const { return fcntl(to ? in_ : out_, F_GETPIPE_SZ); }

lsp_process::lsp_process(const std::vector<std::string>& args) {
  int in[2], out[2], err[2];
  if (pipe(in) != 0 || pipe(out) != 0 || pipe(err) != 0) throw std::runtime_error("pipe");
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, in[0], 0);
  posix_spawn_file_actions_adddup2(&fa, out[1], 1);
  posix_spawn_file_actions_adddup2(&fa, err[1], 2);
  for (int fd : {in[0], in[1], out[0], out[1], err[0], err[1]}) posix_spawn_file_actions_addclose(&fa, fd);
  std::vector<std::string> argv_s{EDSC_BINARY, "lsp"};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  if (posix_spawn(&pid_, EDSC_BINARY, &fa, nullptr, argv.data(), environ) != 0) throw std::runtime_error("spawn");
  posix_spawn_file_actions_destroy(&fa);
  close(in[0]);
  close(out[1]);
  close(err[1]);
  in_ = in[1];
  out_ = out[0];
  err_ = err[0];
  fcntl(out_, F_SETFL, O_NONBLOCK);
  fcntl(err_, F_SETFL, O_NONBLOCK);
  signal(SIGPIPE, SIG_IGN);
}

lsp_process::~lsp_process() {
  if (status_ == -2) {
    if (in_ >= 0) close(in_);
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  if (out_ >= 0) close(out_);
  if (err_ >= 0) close(err_);
}

void lsp_process::send_raw(std::string_view bytes) {
  while (!bytes.empty()) {
    const auto n = write(in_, bytes.data(), bytes.size());
    if (n <= 0) throw std::runtime_error("write to server failed");
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
}

void lsp_process::send(const json& message) {
  const auto body = message.dump();
  send_raw("Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body);
}

void lsp_process::notify(const std::string& method, json params) {
  send(json{{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}});
}

json lsp_process::request(const std::string& method, json params) {
  const int id = next_id();
  send(json{{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}});
  for (;;) {
    auto m = next_message();
    if (!m) throw std::runtime_error("no response to " + method + "; stderr: " + stderr_text());
    if (m->contains("id") && (*m)["id"] == id && !m->contains("method")) return *m;
    pending_.push_back(std::move(*m));
  }
}

json lsp_process::wait_notification(const std::string& method) {
  for (auto it = pending_.begin(); it != pending_.end(); ++it) {
    if (it->value("method", "") == method) {
      auto m = std::move(*it);
      pending_.erase(it);
      return m;
    }
  }
  for (;;) {
    auto m = next_message();
    if (!m) throw std::runtime_error("no " + method + " notification; stderr: " + stderr_text());
    if (m->value("method", "") == method) return *m;
    pending_.push_back(std::move(*m));
  }
}

json lsp_process::initialize(json options) {
  json params{{"processId", nullptr}, {"rootUri", nullptr}, {"capabilities", json::object()}};
  if (!options.is_null()) params["initializationOptions"] = std::move(options);
  auto r = request("initialize", std::move(params));
  notify("initialized", json::object());
  return r;
}

std::optional<json> lsp_process::next_message(std::chrono::milliseconds timeout) {
  const auto deadline = clock::now() + edsc::test_time::scaled(timeout);
  for (;;) {
    const auto header_end = buffer_.find("\r\n\r\n");
    if (header_end != std::string::npos) {
      const auto cl = buffer_.find("Content-Length: ");
      if (cl != 0) throw std::runtime_error("output does not start with Content-Length: " + buffer_.substr(0, 80));
      const std::size_t length = std::stoul(buffer_.substr(16, header_end - 16));
      if (buffer_.size() >= header_end + 4 + length) {
        auto body = buffer_.substr(header_end + 4, length);
        buffer_.erase(0, header_end + 4 + length);
        return json::parse(body);
      }
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - clock::now()).count();
    if (left <= 0) return std::nullopt;
    pollfd p{out_, POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(left)) <= 0) continue;
    char chunk[65536];
    const auto n = read(out_, chunk, sizeof chunk);
    if (n == 0) return std::nullopt;
    if (n > 0) buffer_.append(chunk, static_cast<std::size_t>(n));
  }
}

int lsp_process::wait_exit() {
  if (in_ >= 0) {
    close(in_);
    in_ = -1;
  }
  const auto deadline = clock::now() + edsc::test_time::scaled(std::chrono::seconds(20));
  while (clock::now() < deadline) {
    int st = 0;
    const auto r = waitpid(pid_, &st, WNOHANG);
    if (r == pid_) {
      status_ = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
      return status_;
    }
    // Keep draining output so the server never blocks on a full pipe.
    char chunk[65536];
    while (read(out_, chunk, sizeof chunk) > 0) {}
    usleep(10000);
  }
  return -1;
}

const std::string& lsp_process::stderr_text() {
  char chunk[4096];
  for (;;) {
    const auto n = read(err_, chunk, sizeof chunk);
    if (n <= 0) break;
    stderr_.append(chunk, static_cast<std::size_t>(n));
  }
  return stderr_;
}

std::string apply_edits(std::string text, const json& edits) {
  // Edits do not overlap; apply from the end so earlier offsets stay valid.
  std::vector<std::pair<std::pair<std::size_t, std::size_t>, std::string>> changes;
  for (const auto& e : edits) {
    changes.push_back({{offset_of(text, e.at("range").at("start")), offset_of(text, e.at("range").at("end"))},
                       e.at("newText").get<std::string>()});
  }
  std::sort(changes.begin(), changes.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [r, t] : changes) text.replace(r.first, r.second - r.first, t);
  return text;
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string run_edsc_stdout(const std::string& args) {
  const std::string cmd = std::string(EDSC_BINARY) + " " + args + " 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  char buf[65536];
  for (std::size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  pclose(p);
  return out;
}

std::string file_uri(const std::string& path) { return "file://" + path; }

}  // namespace edsc::lsp_test
