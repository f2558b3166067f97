// The output policy (io/output_target.hpp, docs/cli.md "Output files") for
// every writer against every kind of target: a table of writer x target
// kind, each cell run as a user would. The writers are every option the
// command line model (`edsc _model`) says names a file edsc writes, so a
// writer added later is in the table without anyone adding it; one the test
// cannot drive is a failure, not a gap. Nothing but the named output may
// change, and a non-regular file is never replaced by a regular one.
#include <sys/socket.h>
#include <sys/sysmacros.h>
#include <sys/un.h>

#include <atomic>
#include <cstring>
#include <functional>
#include <map>
#include <thread>

#include "cli/cli_model_support.hpp"
#include "reliability/reliability_support.hpp"
#include "reliability/sim_device.hpp"
#include "test_paths.hpp"

namespace edsc::reliability_test {
namespace {

// Valid (so every command succeeds on it) but not laid out canonically, so
// that `fmt` writes something other than its input.
std::string input_eds() {
  std::string s = good_eds;
  const std::string from = "ProdCode = 1;";
  s.replace(s.find(from), from.size(), "ProdCode =    1 ;");
  return s;
}
const std::string device_json =
    R"({"vendor": 65535, "product_type": 7, "product_code": 9, "name": "Policy Node", "network": "devicenet",
        "input_bytes": 1, "date": "01-02-2024"})";

fs::path eds_in(const fs::path& d) { return d / "in" / "dev.eds"; }
fs::path network_in(const fs::path& d) { return d / "in" / "networks" / "thesis.toml"; }

// What the test gives an argument of each kind the model names, and the files
// that argument makes the command read (a network reads its nodes' EDS files).
struct argument {
  std::string value;
  std::vector<fs::path> reads;
};
std::optional<argument> argument_of(const std::string& kind, const fs::path& d, const std::string& device) {
  if (kind == "eds") return argument{eds_in(d).string(), {eds_in(d)}};
  if (kind == "json") return argument{(d / "in" / "device.json").string(), {d / "in" / "device.json"}};
  if (kind == "toml")
    return argument{network_in(d).string(),
                    {network_in(d), d / "in" / "nodes" / "level.eds", d / "in" / "rightsight-42ef-3byte.eds"}};
  if (kind == "host") return argument{device, {}};
  return std::nullopt;
}

// What a command needs to write beyond its required arguments: `new` takes
// its device from --from or from four options the parser does not require.
const std::map<std::string, std::vector<std::string>> extra_options{{"new", {"--from", "json"}}};

// Commands that need an EDS of another kind than dev.eds (a DeviceNet node):
// `connection` needs an EtherNet/IP connection to print.
const std::map<std::string, std::string> eds_of_command{{"connection", "eip.eds"}};
std::optional<argument> argument_for(const std::string& command, const std::string& kind, const fs::path& d,
                                     const std::string& device) {
  if (const auto it = eds_of_command.find(command); kind == "eds" && it != eds_of_command.end())
    return argument{(d / "in" / it->second).string(), {d / "in" / it->second}};
  return argument_of(kind, d, device);
}

struct writer {
  std::string name;  // "probe --upload-eds"
  // The arguments that write to `target`, given the scratch folder.
  std::function<std::vector<std::string>(const fs::path& dir, const std::string& target)> args;
  // The inputs it reads: an output naming one of them must be refused.
  std::function<std::vector<fs::path>(const fs::path& dir)> inputs;
};

// Every writer of the model, with the arguments to run it: the required ones
// (and extra_options), each given by its kind, then the output. A writer whose
// arguments the test cannot give is a failure naming it.
std::vector<writer> writers(const std::string& device) {
  std::vector<writer> out;
  each_command(cli_model(), [&](const nlohmann::json& c) {
    const auto path = c.at("path").get<std::string>();
    for (const auto& o : c.at("options")) {
      if (o.at("kind") != "output") continue;
      const model_option target_option{path, o};
      // (option spelling, kind) of everything else the command needs.
      std::vector<std::pair<std::string, std::string>> needs;
      for (const auto& other : c.at("options")) {
        if (other == o || !other.at("required").get<bool>()) continue;
        const model_option m{path, other};
        needs.emplace_back(m.positional() ? "" : m.spelling(), m.kind());
      }
      if (const auto it = extra_options.find(path); it != extra_options.end())
        for (std::size_t i = 0; i + 1 < it->second.size(); i += 2) needs.emplace_back(it->second[i], it->second[i + 1]);
      bool drivable = true;
      for (const auto& [spelling, kind] : needs)
        if (!argument_of(kind, "/", device)) {
          ADD_FAILURE() << "edsc " << path << " " << target_option.spelling() << " writes a file, but the test cannot "
                        << "give its argument " << spelling << " of kind '" << kind
                        << "': teach argument_of (or extra_options) how to run it";
          drivable = false;
        }
      if (!drivable) continue;
      writer w;
      w.name = path + " " + target_option.spelling();
      w.args = [=](const fs::path& d, const std::string& target) {
        auto args = words_of(path);
        for (const auto& [spelling, kind] : needs) {
          if (!spelling.empty()) args.push_back(spelling);
          args.push_back(argument_for(path, kind, d, device)->value);
        }
        args.push_back(target_option.spelling());
        args.push_back(target);
        return args;
      };
      w.inputs = [=](const fs::path& d) {
        std::vector<fs::path> reads;
        for (const auto& [spelling, kind] : needs) {
          const auto a = argument_for(path, kind, d, device);
          reads.insert(reads.end(), a->reads.begin(), a->reads.end());
        }
        return reads;
      };
      out.push_back(std::move(w));
    }
  });
  return out;
}

class OutputPolicy : public Cli {
 protected:
  void SetUp() override {
    Cli::SetUp();
    writers_ = writers(device_.address());
    file("in/dev.eds", input_eds());
    file("in/device.json", device_json);
    const fs::path eds = fs::path(EDSC_PROJECT_DIR) / "eds";
    fs::create_directories(dir_ / "in" / "networks");
    fs::copy(eds / "networks" / "thesis.toml", dir_ / "in" / "networks" / "thesis.toml");
    fs::copy(eds / "nodes", dir_ / "in" / "nodes");
    fs::copy(eds / "rightsight-42ef-3byte.eds", dir_ / "in" / "rightsight-42ef-3byte.eds");
    fs::copy(fs::path(EDSC_PROJECT_DIR) / "tests" / "docs" / "workspace" / "device.eds", dir_ / "in" / "eip.eds");
  }

  // Every input's bytes, to show none of them changed.
  std::map<fs::path, std::string> snapshot(const writer& c) {
    std::map<fs::path, std::string> out;
    for (const auto& p : c.inputs(dir_)) out[p] = read_bytes(p);
    return out;
  }

  // The bytes a command writes to a plain new file named `out` in a folder of
  // its own (file names reach some outputs, such as a header's guard).
  std::string reference(const writer& c) {
    const auto d = dir_ / ("ref-" + std::to_string(counter_++));
    fs::create_directory(d);
    const auto r = run_edsc(c.args(dir_, (d / "out").string()), time_limit);
    EXPECT_EQ(r.status, 0) << c.name << "\n" << r.output;
    return read_bytes(d / "out");
  }

  fs::path fresh_dir() {
    const auto d = dir_ / ("t-" + std::to_string(counter_++));
    fs::create_directory(d);
    return d;
  }

  // The device probe --upload-eds uploads from: it serves the input EDS.
  sim_device device_{input_eds()};
  std::vector<writer> writers_;
  int counter_ = 0;
};

// The model is read, and holds every writer known when this test was written.
TEST_F(OutputPolicy, EveryWriterOfTheModelIsInTheTable) {
  std::vector<std::string> names;
  for (const auto& w : writers_) names.push_back(w.name);
  for (const char* known : {"fmt --output", "fix --output", "edit --output", "header --output", "doc --output",
                            "new --output", "net map --output", "probe --upload-eds"})
    EXPECT_NE(std::find(names.begin(), names.end(), known), names.end()) << known;
}

TEST_F(OutputPolicy, RegularTargetsAreWrittenAtomically) {
  for (const auto& c : writers_) {
    const auto want = reference(c);
    ASSERT_FALSE(want.empty()) << c.name;
    // An existing file that is not an input is replaced whole.
    const auto d = fresh_dir();
    write_bytes(d / "out", std::string(100000, 'x'));
    const auto r = run_edsc(c.args(dir_, (d / "out").string()), time_limit);
    EXPECT_EQ(r.status, 0) << c.name << "\n" << r.output;
    EXPECT_EQ(read_bytes(d / "out"), want) << c.name;
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(d / "out"))) << c.name;
  }
}

TEST_F(OutputPolicy, TheInputIsRefusedHoweverItIsNamed) {
  for (const auto& c : writers_) {
    const auto before = snapshot(c);
    for (const auto& in : c.inputs(dir_)) {
      const auto d = fresh_dir();
      fs::create_symlink(in, d / "link");
      fs::create_hard_link(in, d / "hard");
      const std::vector<std::string> spellings{in.string(), (in.parent_path() / "." / in.filename()).string(),
                                               (d / "link").string(), (d / "hard").string()};
      for (const auto& t : spellings) {
        const auto r = run_edsc(c.args(dir_, t), time_limit);
        EXPECT_EQ(r.status, 2) << c.name << " -o " << t << "\n" << r.output;
        EXPECT_NE(r.output.find("edsc: error: "), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("refusing to overwrite the input"), std::string::npos) << c.name << " -o " << t << "\n"
                                                                                       << r.output;
      }
      EXPECT_TRUE(fs::is_symlink(d / "link")) << c.name;
    }
    EXPECT_EQ(snapshot(c), before) << c.name;
  }
}

TEST_F(OutputPolicy, MissingFolderAndDirectoryAreRefused) {
  for (const auto& c : writers_) {
    const auto d = fresh_dir();
    auto r = run_edsc(c.args(dir_, (d / "nowhere" / "out").string()), time_limit);
    EXPECT_EQ(r.status, 2) << c.name << "\n" << r.output;
    EXPECT_NE(r.output.find("does not exist"), std::string::npos) << c.name << "\n" << r.output;
    EXPECT_FALSE(fs::exists(d / "nowhere")) << c.name;
    fs::create_directory(d / "dir");
    r = run_edsc(c.args(dir_, (d / "dir").string()), time_limit);
    EXPECT_EQ(r.status, 2) << c.name << "\n" << r.output;
    EXPECT_NE(r.output.find("is a directory"), std::string::npos) << c.name << "\n" << r.output;
    EXPECT_TRUE(fs::is_directory(d / "dir") && fs::is_empty(d / "dir")) << c.name;
  }
}

TEST_F(OutputPolicy, DashIsStandardOutputEverywhere) {
  for (const auto& c : writers_) {
    const auto d = fresh_dir();
    const auto r = run_edsc(c.args(dir_, "-"), time_limit);
    EXPECT_EQ(r.status, 0) << c.name << "\n" << r.output;
    EXPECT_GT(r.output.size(), 100u) << c.name;
    EXPECT_FALSE(fs::exists("-")) << c.name;
    EXPECT_FALSE(fs::exists(dir_ / "-")) << c.name;
  }
}

TEST_F(OutputPolicy, AFifoIsWrittenThroughAndStaysAFifo) {
  for (const auto& c : writers_) {
    const auto want = reference(c);
    const auto d = fresh_dir();
    ASSERT_EQ(::mkfifo((d / "out").c_str(), 0600), 0);
    // A reader first (non-blocking), so the writer's open does not wait, and
    // on its own thread, so an output larger than the pipe cannot stall it.
    const int rd = ::open((d / "out").c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    ASSERT_GE(rd, 0);
    std::atomic<bool> done{false};
    std::string got;
    std::thread reader([&] {
      char buf[65536];
      for (;;) {
        pollfd p{rd, POLLIN, 0};
        ::poll(&p, 1, 20);
        const ssize_t n = ::read(rd, buf, sizeof buf);
        if (n > 0)
          got.append(buf, static_cast<std::size_t>(n));
        else if (done)
          break;  // no writer left and edsc has ended: all read
      }
    });
    const auto r = run_edsc(c.args(dir_, (d / "out").string()), time_limit);
    done = true;
    reader.join();
    ::close(rd);
    EXPECT_EQ(r.status, 0) << c.name << "\n" << r.output;
    EXPECT_EQ(got, want) << c.name;
    EXPECT_TRUE(fs::is_fifo(fs::symlink_status(d / "out"))) << c.name;
  }
}

TEST_F(OutputPolicy, ASymlinkIsWrittenThroughAndStaysALink) {
  for (const auto& c : writers_) {
    const auto want = reference(c);
    const auto d = fresh_dir();
    fs::create_directory(d / "real");
    write_bytes(d / "real" / "out", "old");
    fs::create_symlink(fs::path("real") / "out", d / "out");
    const auto r = run_edsc(c.args(dir_, (d / "out").string()), time_limit);
    EXPECT_EQ(r.status, 0) << c.name << "\n" << r.output;
    EXPECT_TRUE(fs::is_symlink(d / "out")) << c.name;
    EXPECT_EQ(read_bytes(d / "real" / "out"), want) << c.name;
    // The replacement was made beside the target: no temporary left anywhere.
    EXPECT_EQ(std::distance(fs::directory_iterator(d / "real"), fs::directory_iterator{}), 1) << c.name;
    EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator{}), 2) << c.name;
  }
}

TEST_F(OutputPolicy, ADanglingSymlinkAndASocketAreRefused) {
  for (const auto& c : writers_) {
    const auto d = fresh_dir();
    fs::create_symlink(d / "nothing", d / "out");
    auto r = run_edsc(c.args(dir_, (d / "out").string()), time_limit);
    EXPECT_EQ(r.status, 2) << c.name << "\n" << r.output;
    EXPECT_NE(r.output.find("symbolic link to nothing"), std::string::npos) << c.name << "\n" << r.output;
    EXPECT_TRUE(fs::is_symlink(d / "out"));
    EXPECT_FALSE(fs::exists(d / "nothing"));

    const int s = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    ASSERT_GE(s, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    const auto sock = (d / "sock").string();
    ASSERT_LT(sock.size(), sizeof addr.sun_path);
    std::memcpy(addr.sun_path, sock.c_str(), sock.size() + 1);
    ASSERT_EQ(::bind(s, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
    r = run_edsc(c.args(dir_, sock), time_limit);
    ::close(s);
    EXPECT_EQ(r.status, 2) << c.name << "\n" << r.output;
    EXPECT_NE(r.output.find("is a socket"), std::string::npos) << c.name << "\n" << r.output;
    EXPECT_TRUE(fs::is_socket(fs::symlink_status(sock))) << c.name;
  }
}

// Device nodes need root (CAP_MKNOD), as CI has. The nodes are made in the
// scratch folder: the machine's own /dev is never a target of a test.
TEST_F(OutputPolicy, DevicesAreWrittenThroughOrRefusedNeverReplaced) {
  const auto null_dev = dir_ / "null";
  if (::mknod(null_dev.c_str(), S_IFCHR | 0666, ::makedev(1, 3)) != 0)
    GTEST_SKIP() << "mknod needs root (CAP_MKNOD): " << std::strerror(errno);
  // A block device node that names no disk of this machine (loop minor 250):
  // refused before it is opened, whatever it would be.
  const auto blk = dir_ / "blk";
  ASSERT_EQ(::mknod(blk.c_str(), S_IFBLK | 0600, ::makedev(7, 250)), 0) << std::strerror(errno);
  for (const auto& c : writers_) {
    auto r = run_edsc(c.args(dir_, null_dev.string()), time_limit);
    EXPECT_EQ(r.status, 0) << c.name << "\n" << r.output;
    EXPECT_TRUE(fs::is_character_file(fs::symlink_status(null_dev))) << c.name;
    r = run_edsc(c.args(dir_, blk.string()), time_limit);
    EXPECT_EQ(r.status, 2) << c.name << "\n" << r.output;
    EXPECT_NE(r.output.find("is a block device"), std::string::npos) << c.name << "\n" << r.output;
    EXPECT_TRUE(fs::is_block_file(fs::symlink_status(blk))) << c.name;
  }
}

TEST_F(OutputPolicy, InPlaceThroughASymlinkKeepsTheLink) {
  const auto real = file("real/dev.eds", input_eds());
  fs::create_symlink(real, dir_ / "link.eds");
  const auto r = run_edsc({"fmt", "--in-place", (dir_ / "link.eds").string()}, time_limit);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.eds"));
  EXPECT_NE(read_bytes(real), input_eds());
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "real"), fs::directory_iterator{}), 1);
}

TEST_F(OutputPolicy, ASiteIsNotWrittenIntoTheFolderItDocuments) {
  const auto lib = dir_ / "in" / "nodes";
  auto r = run_edsc({"doc", lib.string(), "-o", lib.string()}, time_limit);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("cannot go into the folder it documents"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(lib / "index.html"));
  // A new folder inside the library is fine: it holds no source.
  r = run_edsc({"doc", lib.string(), "-o", (lib / "site").string()}, time_limit);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(lib / "site" / "index.html"));
}

// Runs `args` through the shell with `redirections` (`>>out`, `5>>out`), as a
// user names a stream; the exit status, or 128 when killed. Appended piece
// by piece: GCC 12 warns falsely (-Wrestrict) on "..." + std::string&&.
int run_redirected(const std::vector<std::string>& args, const std::string& redirections) {
  std::string cmd = "timeout -s KILL ";
  cmd += std::to_string(edsc::test_time::scaled(time_limit).count());
  cmd += ' ';
  cmd += shell_quote(EDSC_BINARY);
  for (const auto& a : args) {
    cmd += ' ';
    cmd += shell_quote(a);
  }
  cmd += " </dev/null ";
  cmd += redirections;
  const int ws = std::system(cmd.c_str());
  return WIFEXITED(ws) ? WEXITSTATUS(ws) : 128;
}

// A name of an open stream is written through that descriptor, where it is:
// with the stream a regular file opened for append (`>>`), whatever the file
// held before stays, and edsc's output follows it. Replacing or reopening
// the file the name resolves to (what a name of a regular file gets) would
// lose it; that only shows when the stream is a file, not a pipe.
TEST_F(OutputPolicy, StreamNamesAppendToAFileOpenedForAppend) {
  struct stream {
    std::string name;
    int fd;  // the descriptor the shell opens the file on
  };
  const std::vector<stream> streams{
      {"-", 1}, {"/dev/stdout", 1}, {"/dev/stderr", 2}, {"/dev/fd/5", 5}, {"/proc/self/fd/5", 5}};
  const std::string before = "held before edsc ran\n";
  for (const auto& c : writers_) {
    for (const auto& s : streams) {
      const auto d = fresh_dir();
      // The other standard streams go to a file of their own, so that what
      // lands on the named stream is its output alone.
      const std::string rest =
          s.fd == 2 ? " >" + shell_quote((d / "rest").string()) : " 2>" + shell_quote((d / "rest").string());
      // What the stream gets when its file starts empty...
      const auto alone = (d / "alone").string();
      int status = run_redirected(c.args(dir_, s.name), std::to_string(s.fd) + ">" + shell_quote(alone) + rest);
      EXPECT_EQ(status, 0) << c.name << " -o " << s.name << "\n" << read_bytes(d / "rest");
      const auto output = read_bytes(alone);
      EXPECT_GT(output.size(), 100u) << c.name << " -o " << s.name << ": nothing on the stream";
      // ... follows what the file held when it was opened for append.
      const auto appended = d / "appended";
      write_bytes(appended, before);
      struct stat st0 {};
      ASSERT_EQ(::stat(appended.c_str(), &st0), 0);
      status =
          run_redirected(c.args(dir_, s.name), std::to_string(s.fd) + ">>" + shell_quote(appended.string()) + rest);
      EXPECT_EQ(status, 0) << c.name << " -o " << s.name << "\n" << read_bytes(d / "rest");
      const auto got = read_bytes(appended);
      EXPECT_TRUE(got.starts_with(before)) << c.name << " -o " << s.name << ": what the file held is lost";
      EXPECT_TRUE(got.size() >= before.size() && got.substr(before.size()) == output)
          << c.name << " -o " << s.name << ": " << got.size() << " bytes, not the " << before.size() << " held and the "
          << output.size() << " of the output";
      struct stat st1 {};
      ASSERT_EQ(::stat(appended.c_str(), &st1), 0);
      EXPECT_EQ(st1.st_ino, st0.st_ino) << c.name << " -o " << s.name << ": the file was replaced";
    }
  }
}

// A stream name whose descriptor is not open is an error, not a file made
// under /proc or /dev.
TEST_F(OutputPolicy, AStreamNameOfAClosedDescriptorIsRefused) {
  const auto r = run_edsc({"header", eds_in(dir_).string(), "-o", "/dev/fd/999999"}, time_limit);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("/dev/fd/999999: no such open stream"), std::string::npos) << r.output;
}

// The raw atomic write is internal to compiler/io (output_target.cpp): no
// other source of the compiler opens a file for writing, renames or copies
// one; every writer goes through io::write_output and its policy.
TEST(OutputPolicySources, NothingOutsideIoWritesAFileItself) {
  const std::vector<std::string> raw{"ofstream",
                                     "std::fstream",
                                     "fopen(",
                                     "O_WRONLY",
                                     "O_RDWR",
                                     "O_CREAT",
                                     "O_TRUNC",
                                     "creat(",
                                     "mkstemp",
                                     "::rename(",
                                     "std::rename(",
                                     "fs::rename(",
                                     "filesystem::rename(",
                                     "copy_file",
                                     "fs::copy(",
                                     "filesystem::copy(",
                                     "write_atomically",
                                     "write_fully",
                                     "io/write_file.hpp"};
  const auto compiler = fs::path(EDSC_PROJECT_DIR) / "compiler";
  std::size_t files = 0;
  for (const auto& e : fs::recursive_directory_iterator(compiler)) {
    const auto rel = fs::relative(e.path(), compiler).string();
    if (!e.is_regular_file() || rel.starts_with("deps/")) continue;
    if (e.path().extension() != ".cpp" && e.path().extension() != ".hpp") continue;
    ++files;
    const bool io = rel.starts_with("io/");
    std::istringstream lines(read_bytes(e.path()));
    int n = 0;
    for (std::string line; std::getline(lines, line);) {
      ++n;
      for (const auto& r : raw) {
        // Inside io, only its own implementation may name the raw write.
        if (io && e.path().extension() == ".cpp") continue;
        if (line.find(r) != std::string::npos)
          ADD_FAILURE() << "compiler/" << rel << ":" << n << " uses " << r
                        << "; write through io::write_output (io/output_target.hpp)\n  " << line;
      }
    }
  }
  EXPECT_GE(files, 100u);
}

}  // namespace
}  // namespace edsc::reliability_test
