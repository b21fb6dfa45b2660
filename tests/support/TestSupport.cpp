#include "tests/support/TestSupport.h"

#include "image_files/PngFile.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "scene/InputError.h"

#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoNode.h>

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

extern char** environ;

namespace ivshadow::test {
namespace {

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

}  // namespace

std::string scenesDir() {
  return IVSHADOW_SCENES_DIR;
}
std::string ivshadowExe() {
  return IVSHADOW_EXE;
}
std::string viewerExe() {
  return IVSHADOW_VIEWER_EXE;
}

std::string outputDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string(info->test_suite_name()) + "." + info->name();
  for (char& c : name) {
    if (c == '/') c = '_';
  }
  const std::filesystem::path dir = std::filesystem::path(IVSHADOW_TEST_OUTPUT_DIR) / name;
  // Emptied once per test, so files from an earlier run never pass for this run's output.
  static std::string emptiedFor;
  if (emptiedFor != name) {
    std::filesystem::remove_all(dir);
    emptiedFor = name;
  }
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::string writeOutputFile(const std::string& name, const std::string& bytes) {
  const std::string path = outputDir() + "/" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

std::string readText(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

int startProcess(const std::vector<std::string>& arguments,
                 const std::vector<std::string>& environment, const std::string& outPath,
                 const std::string& errPath) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&actions, 2, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  std::vector<char*> argv;
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::vector<std::string> envStrings;
  for (char** e = environ; *e != nullptr; ++e) envStrings.emplace_back(*e);
  for (const std::string& e : environment) {
    const std::string key = e.substr(0, e.find('=') + 1);
    envStrings.erase(std::remove_if(envStrings.begin(), envStrings.end(),
                                    [&](const std::string& s) { return s.rfind(key, 0) == 0; }),
                     envStrings.end());
    if (e.back() != '=') envStrings.push_back(e);  // "NAME=" unsets NAME
  }
  std::vector<char*> envp;
  for (const std::string& e : envStrings) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);
  pid_t pid = 0;
  const bool started =
      posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), envp.data()) == 0;
  posix_spawn_file_actions_destroy(&actions);
  return started ? pid : -1;
}

int waitForProcess(int pid) {
  int status = 0;
  if (pid <= 0 || waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

ProcessResult run(const std::vector<std::string>& arguments,
                  const std::vector<std::string>& environment) {
  const std::string base =
      std::filesystem::temp_directory_path() / ("ivshadow-test-" + std::to_string(::getpid()));
  const std::string outPath = base + ".out", errPath = base + ".err";
  ProcessResult result;
  result.exitCode = waitForProcess(startProcess(arguments, environment, outPath, errPath));
  result.out = readAll(outPath);
  result.err = readAll(errPath);
  std::filesystem::remove(outPath);
  std::filesystem::remove(errPath);
  return result;
}

std::string inputErrorOf(const std::function<void()>& body) {
  try {
    body();
  } catch (const InputError& error) {
    return error.what();
  }
  return {};
}

bool fileExists(const std::string& path) {
  return std::filesystem::exists(path);
}

int interruptWhileWriting(const std::vector<std::string>& arguments, const std::string& dir,
                          const std::string& fifo, int signal) {
  if (::mkfifo(fifo.c_str(), 0600) != 0) return -1;
  const int pid = startProcess(arguments, {}, fifo + ".stdout", fifo + ".stderr");
  if (pid <= 0) return -1;
  const auto temporary = [&] {
    for (const std::string& name : filesIn(dir))
      if (name[0] == '.') return true;
    return false;
  };
  // A poll, not a timing: the temporary exists until the FIFO has a reader.
  for (int i = 0; i < 1500 && !temporary(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ::kill(pid, signal);
  // Non-blocking: should the command be gone, nothing waits for a writer that never comes.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  const int status = waitForProcess(pid);
  if (reader >= 0) ::close(reader);
  return status;
}

std::vector<std::string> filesIn(const std::string& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.find_first_not_of(" \t\r") != std::string::npos) out.push_back(line);
  }
  return out;
}

std::string compareWithExpectation(const Image& actual, const ExpectedImage& expected,
                                   double tolerance) {
  Image expectedImage(actual.width(), actual.height());
  Image diff(actual.width(), actual.height());
  int failures = 0, checked = 0;
  double worst = 0.0;
  int worstX = 0, worstY = 0;
  for (int y = 0; y < actual.height(); ++y) {
    for (int x = 0; x < actual.width(); ++x) {
      const Expectation e = expected(x, y);
      const std::uint8_t* a = actual.pixel(x, y);
      std::uint8_t* ex = expectedImage.pixel(x, y);
      std::uint8_t* d = diff.pixel(x, y);
      d[3] = ex[3] = 255;
      if (!e.checked) continue;
      ++checked;
      double error = 0.0;
      for (int c = 0; c < 3; ++c) {
        ex[c] = static_cast<std::uint8_t>(std::lround(std::clamp(e.rgb[c], 0.0, 255.0)));
        error = std::max(error, std::abs(a[c] - e.rgb[c]));
      }
      if (error > worst) {
        worst = error;
        worstX = x;
        worstY = y;
      }
      if (error > tolerance) {
        ++failures;
        d[0] = 255;
      } else {
        d[0] = d[1] = d[2] = static_cast<std::uint8_t>(a[1] / 3);
      }
    }
  }
  if (failures == 0 && checked > 0) return {};
  const std::string dir = outputDir();
  writePng(dir + "/actual.png", actual);
  writePng(dir + "/expected.png", expectedImage);
  writePng(dir + "/diff.png", diff);
  std::ostringstream message;
  message << failures << " of " << checked << " checked pixels differ by more than " << tolerance
          << "; worst " << worst << " at (" << worstX << ", " << worstY << "); images in " << dir;
  return message.str();
}

ImageComparison renderAgainstReference(const std::string& scene, const std::string& size,
                                       const std::vector<std::string>& renderArguments,
                                       double psnrFloor) {
  const std::string dir = outputDir();
  std::vector<std::string> render = {ivshadowExe(),       "render", scene, "-o",
                                     dir + "/actual.png", "--size", size};
  render.insert(render.end(), renderArguments.begin(), renderArguments.end());
  const ProcessResult gl = run(render);
  EXPECT_EQ(gl.exitCode, 0) << gl.err;
  const ProcessResult exact =
      run({ivshadowExe(), "reference", scene, "-o", dir + "/reference.png", "--size", size});
  EXPECT_EQ(exact.exitCode, 0) << exact.err;
  if (gl.exitCode != 0 || exact.exitCode != 0) return ImageComparison{};
  const Image actual = readPng(dir + "/actual.png"), reference = readPng(dir + "/reference.png");
  const ImageComparison metrics = ImageComparison::compare(reference, actual, "reference", "gl");
  if (metrics.all.psnr < psnrFloor) writePng(dir + "/diff.png", errorHeatMap(reference, actual, 0));
  return metrics;
}

void setOnEveryGroup(SoNode* root, const std::string& field) {
  SoSearchAction search;
  search.setType(SoTransparentShadowGroup::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  for (int i = 0; i < search.getPaths().getLength(); ++i)
    EXPECT_TRUE(search.getPaths()[i]->getTail()->set(field.c_str())) << field;
}

}  // namespace ivshadow::test
