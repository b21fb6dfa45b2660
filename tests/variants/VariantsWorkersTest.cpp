// `ivshadow variants` renders through long-lived workers (cli/RenderWorkers.h); each worker
// renders variant after variant in one GL context. These tests hold the workers to what one
// `ivshadow render` process per variant gave: the same pixels, messages, reports and exit
// statuses, warnings said per variant, and a crash kept to its variant.
#include "image_files/PngFile.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

namespace ivshadow {
namespace {

using test::readText;

// Without workers: one `ivshadow render` process per variant, as before them.
const std::vector<std::string> kOneProcessPerVariant = {"IVSHADOW_VARIANTS_WORKERS=0"};

std::string coloured() {
  return test::scenesDir() + "/coloured_shadows.iv";
}

// Whether two PNG files hold the same pixels, to the bit; the message says how they differ.
::testing::AssertionResult samePixels(const std::string& a, const std::string& b) {
  const Image first = readPng(a);
  const Image second = readPng(b);
  if (first.width() != second.width() || first.height() != second.height())
    return ::testing::AssertionFailure()
           << a << " is " << first.width() << "x" << first.height() << ", " << b << " "
           << second.width() << "x" << second.height();
  const std::size_t bytes = std::size_t(first.width()) * std::size_t(first.height()) * 4;
  if (std::memcmp(first.data(), second.data(), bytes) != 0)
    return ::testing::AssertionFailure() << a << " and " << b << " differ in their pixels";
  return ::testing::AssertionSuccess();
}

nlohmann::json manifest(const std::string& dir, const std::string& name) {
  return nlohmann::json::parse(readText(dir + "/manifests/" + name + ".json"));
}

// The sweep's own child processes still running (its workers), by /proc.
std::vector<int> childrenOf(int parent) {
  std::vector<int> children;
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(entry.path() / "stat");
    std::string text;
    std::getline(stat, text);
    // "PID (COMM) STATE PPID ...": the command may hold spaces and parentheses.
    const std::size_t close = text.rfind(')');
    if (close == std::string::npos) continue;
    char state = 0;
    int ppid = 0;
    if (std::sscanf(text.c_str() + close + 1, " %c %d", &state, &ppid) != 2) continue;
    if (ppid == parent && state != 'Z') children.push_back(std::stoi(name));
  }
  return children;
}

// Waits (10 s at most) until `ready` holds; whether it did.
bool waitUntil(const std::function<bool()>& ready) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (std::chrono::steady_clock::now() < deadline) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  return false;
}

// One worker (--jobs 1) renders every variant in turn, so that whatever a variant could leave
// behind in the worker (GL state, Coin's caches, the warnings said once) meets the next:
// GL's path after the traced one and back, a failed variant in the middle, settings that do
// nothing said for each variant that makes them. The worker keeps the scene from a traced
// variant to the next (cli/KeptScene.h): the last variants assign other fields one after
// another on the scene kept, a light's, a material's, none, a value that does not parse (the
// scene is then read afresh), the light's again, then move and dim it, so that the tracer
// shades the surfaces it kept. Each picture must equal, to the bit, the one its own `ivshadow
// render` process draws; the stderr, stdout, exit status, manifests and CSV must be those of
// one process per variant.
TEST(VariantsWorkers, RenderTheSweepOfOneProcessPerVariantToTheBit) {
  const std::string dir = test::outputDir();
  const std::string file = dir + "/mixed.variants";
  std::ofstream(file) << "variant traced\n  Lamp.intensity = 0.8\n"
                         "variant raster_map\n  Scene.renderer = RASTER\n  Lamp.method = MAP\n"
                         "  Lamp.resolution = 128\n"
                         "variant traced_again\n  RedPaneMaterial.diffuseColor = 0.2 0.3 1\n"
                         "variant raster_rays\n  Scene.renderer = RASTER\n  Lamp.method = RAYS\n"
                         "variant typo\n  Lamp.colour = 1 0 0\n"
                         "sweep idle Lamp.resolution = 128 | 256\n  Scene.renderer = TRACER\n"
                         "variant bright\n  RedPaneMaterial.diffuseColor = 1.7 0.1 0.1\n"
                         "variant lamp\n  Lamp.intensity = 0.6\n"
                         "variant pane\n  RedPaneMaterial.transparency = 0.3\n"
                         "variant plain\n"
                         "variant unparsable\n  Lamp.intensity = bright\n"
                         "variant lamp_again\n  Lamp.intensity = 0.7\n"
                         "variant lamp_moved\n  Lamp.location = 0.6 -0.4 4\n"
                         "variant lamp_dim\n  Lamp.intensity = 0.5\n";
  const std::vector<std::string> names = {
      "traced", "raster_map", "traced_again", "raster_rays", "idle-128",   "idle-256", "bright",
      "lamp",   "pane",       "plain",        "lamp_again",  "lamp_moved", "lamp_dim"};
  const auto sweep = [&](const std::string& out) {
    return std::vector<std::string>{
        test::ivshadowExe(), "variants", coloured(), file, "-o", out, "--size", "96x72",
        "--frames",          "2",        "--jobs",   "1"};
  };
  const test::ProcessResult workers = test::run(sweep(dir + "/workers"));
  const test::ProcessResult processes = test::run(sweep(dir + "/processes"), kOneProcessPerVariant);
  // The bad variant makes both exit 2, after the others rendered.
  EXPECT_EQ(workers.exitCode, 2) << workers.err;
  EXPECT_EQ(processes.exitCode, 2) << processes.err;
  // The progress lines, the bad variant's error and the settings that did nothing, in order.
  EXPECT_EQ(workers.err, processes.err);
  EXPECT_NE(workers.err.find(file + ":13: error: variant typo: "), std::string::npos)
      << workers.err;
  EXPECT_NE(workers.err.find("resolution does nothing"), std::string::npos) << workers.err;
  std::string out = processes.out;
  out.replace(out.find(dir + "/processes"), (dir + "/processes").size(), dir + "/workers");
  EXPECT_EQ(workers.out, out);

  for (const std::string& name : names) {
    EXPECT_TRUE(samePixels(dir + "/workers/" + name + ".png", dir + "/processes/" + name + ".png"))
        << name;
    const nlohmann::json byWorker = manifest(dir + "/workers", name);
    const nlohmann::json byProcess = manifest(dir + "/processes", name);
    EXPECT_EQ(byWorker["exit_code"], 0) << name;
    for (const char* key : {"idle_settings", "dsm_bytes", "bvh_bytes", "dsm_layers_used",
                            "tracer_frames", "ray_frames", "width", "height", "frames"})
      EXPECT_EQ(byWorker["stats"].value(key, nlohmann::json()),
                byProcess["stats"].value(key, nlohmann::json()))
          << name << ": " << key;
    EXPECT_EQ(byWorker["stats"]["passes"]["shadow_method"],
              byProcess["stats"]["passes"]["shadow_method"])
        << name;
  }
  // The two settings that did nothing in a traced group, reported under each variant that
  // set them though one worker rendered both.
  EXPECT_EQ(manifest(dir + "/workers", "idle-256")["stats"]["idle_settings"].size(), 1u);
  for (const char* failed : {"typo", "unparsable"}) {
    const nlohmann::json byWorker = manifest(dir + "/workers", failed);
    EXPECT_EQ(byWorker["exit_code"], 2) << failed;
    EXPECT_EQ(byWorker["error"], manifest(dir + "/processes", failed)["error"]) << failed;
  }
  // The light's variants on the scene kept: the first read the lights alone, the others
  // shaded the surfaces kept; the same pictures as the processes' all the same.
  for (const char* kept : {"lamp_moved", "lamp_dim"})
    EXPECT_EQ(manifest(dir + "/workers", kept)["stats"]["tracer_scenes"], 0) << kept;

  // The CSV but for its timing columns (frame_ms_median and the build and trace times).
  const std::vector<std::string> byWorkers = test::lines(readText(dir + "/workers/variants.csv"));
  const std::vector<std::string> byProcesses =
      test::lines(readText(dir + "/processes/variants.csv"));
  ASSERT_EQ(byWorkers.size(), names.size() + 3);
  ASSERT_EQ(byWorkers.size(), byProcesses.size());
  const auto untimed = [](const std::string& line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (char c : line) {
      if (c == '"') quoted = !quoted;
      if (c == ',' && !quoted)
        fields.emplace_back();
      else
        fields.back() += c;
    }
    for (std::size_t timed : {4, 5, 6, 7, 8})
      if (timed < fields.size()) fields[timed].clear();
    return fields;
  };
  for (std::size_t row = 0; row < byWorkers.size(); ++row)
    EXPECT_EQ(untimed(byWorkers[row]), untimed(byProcesses[row])) << byWorkers[row];
}

// Warnings said once per process (a diffuse colour outside 0..1 is one for the whole process)
// are said again for each scene a worker renders, into that render's log: the logs of two
// identical requests are identical, and hold what `ivshadow render` says.
TEST(VariantsWorkers, AWorkerSaysEachRendersWarningsInItsOwnLog) {
  const std::string dir = test::outputDir();
  const nlohmann::json request = {{"scene", coloured()},
                                  {"size", "64x48"},
                                  {"frames", 1},
                                  {"sets", {"RedPaneMaterial.diffuseColor=1.7 0.1 0.1"}},
                                  {"transparency", ""}};
  std::ofstream requests(dir + "/requests");
  for (const char* name : {"first", "second"}) {
    nlohmann::json r = request;
    r["output"] = dir + "/" + name + ".png";
    r["stats"] = dir + "/" + name + ".json";
    r["log"] = dir + "/" + name + ".log";
    requests << r.dump() << '\n';
  }
  requests.close();
  const test::ProcessResult worker =
      test::run({"/bin/sh", "-c", "exec \"$0\" variants-worker < \"$1\"", test::ivshadowExe(),
                 dir + "/requests"});
  EXPECT_EQ(worker.exitCode, 0) << worker.err;
  EXPECT_EQ(worker.out, "{\"exit\":0,\"last\":false}\n{\"exit\":0,\"last\":false}\n");
  EXPECT_EQ(worker.err, "") << "between renders a worker has nothing to say";
  const std::string first = readText(dir + "/first.log");
  EXPECT_NE(first.find("a diffuse colour of 1.7"), std::string::npos) << first;
  EXPECT_EQ(readText(dir + "/second.log"), first);
  EXPECT_TRUE(samePixels(dir + "/first.png", dir + "/second.png"));

  const test::ProcessResult render =
      test::run({test::ivshadowExe(), "render", coloured(), "-o", dir + "/render.png", "--size",
                 "64x48", "--frames", "1", "--set", "RedPaneMaterial.diffuseColor=1.7 0.1 0.1"});
  ASSERT_EQ(render.exitCode, 0) << render.err;
  EXPECT_EQ(render.err, first);
  EXPECT_TRUE(samePixels(dir + "/render.png", dir + "/second.png"));
}

// What one render sets on the worker's renderer is not the next one's: a --transparency type
// is not kept by a render without one, and a render of another size gets a framebuffer of
// its size (Python's render() sends such requests). Each picture equals `ivshadow render`'s.
TEST(VariantsWorkers, AWorkerRendersWhatEachRequestAsksNotWhatTheLastOneSet) {
  const std::string dir = test::outputDir();
  // GL's path blending with Coin, where the transparency type changes the picture.
  const std::vector<std::string> sets = {"Scene.renderer=RASTER",
                                         "Scene.transparency=COIN_BLENDING"};
  const struct {
    const char* name;
    const char* size;
    const char* transparency;
  } renders[] = {{"sorted", "96x72", "SORTED_OBJECT_BLEND"},
                 {"default", "96x72", ""},
                 {"smaller", "64x48", "BLEND"}};
  std::ofstream requests(dir + "/requests");
  for (const auto& r : renders)
    requests << nlohmann::json({{"scene", coloured()},
                                {"output", dir + "/" + r.name + ".png"},
                                {"size", r.size},
                                {"frames", 1},
                                {"stats", dir + "/" + r.name + ".json"},
                                {"sets", sets},
                                {"transparency", r.transparency},
                                {"log", dir + "/" + r.name + ".log"}})
                    .dump()
             << '\n';
  requests.close();
  const test::ProcessResult worker =
      test::run({"/bin/sh", "-c", "exec \"$0\" variants-worker < \"$1\"", test::ivshadowExe(),
                 dir + "/requests"});
  ASSERT_EQ(worker.exitCode, 0) << worker.err;
  for (const auto& r : renders) {
    std::vector<std::string> command = {test::ivshadowExe(),
                                        "render",
                                        coloured(),
                                        "-o",
                                        dir + "/" + r.name + "-render.png",
                                        "--size",
                                        r.size,
                                        "--frames",
                                        "1"};
    for (const std::string& set : sets) command.insert(command.end(), {"--set", set});
    if (*r.transparency != 0) command.insert(command.end(), {"--transparency", r.transparency});
    const test::ProcessResult render = test::run(command);
    ASSERT_EQ(render.exitCode, 0) << render.err;
    EXPECT_TRUE(samePixels(dir + "/" + r.name + ".png", dir + "/" + r.name + "-render.png"))
        << r.name;
  }
  EXPECT_FALSE(samePixels(dir + "/sorted.png", dir + "/default.png"))
      << "the transparency type must change this picture for the test to mean anything";
}

// A render that fails for a reason other than bad input (here: no GL context) may leave its
// worker in any state: the worker answers and ends, unasked requests unanswered, and a fresh
// one takes the next variant. The sweep says and files what one process per variant did.
TEST(VariantsWorkers, AFailedRenderEndsItsWorkerAndFailsAsItsProcessDid) {
  const std::string dir = test::outputDir();
  const std::vector<std::string> noContext = {"IVSHADOW_EGL_PLATFORM=nowhere"};
  std::ofstream requests(dir + "/requests");
  for (const char* name : {"first", "second"})
    requests << nlohmann::json({{"scene", coloured()},
                                {"output", dir + "/" + name + ".png"},
                                {"size", "64x48"},
                                {"frames", 1},
                                {"stats", dir + "/" + name + ".json"},
                                {"sets", nlohmann::json::array()},
                                {"transparency", ""},
                                {"log", dir + "/" + name + ".log"}})
                    .dump()
             << '\n';
  requests.close();
  const test::ProcessResult worker =
      test::run({"/bin/sh", "-c", "exec \"$0\" variants-worker < \"$1\"", test::ivshadowExe(),
                 dir + "/requests"},
                noContext);
  EXPECT_EQ(worker.exitCode, 3);
  EXPECT_EQ(worker.out, "{\"exit\":3,\"last\":true}\n");
  EXPECT_NE(readText(dir + "/first.log").find("IVSHADOW_EGL_PLATFORM=nowhere is not available"),
            std::string::npos)
      << readText(dir + "/first.log");
  EXPECT_FALSE(test::fileExists(dir + "/second.log"));

  const std::string file = dir + "/three.variants";
  std::ofstream(file) << "sweep light Lamp.intensity = 0.4 | 0.6 | 0.8\n";
  const auto sweep = [&](const std::string& out) {
    return std::vector<std::string>{
        test::ivshadowExe(), "variants", coloured(), file, "-o", out, "--size", "64x48",
        "--frames",          "1",        "--jobs",   "1"};
  };
  const test::ProcessResult workers = test::run(sweep(dir + "/workers"), noContext);
  std::vector<std::string> environment = noContext;
  environment.push_back(kOneProcessPerVariant[0]);
  const test::ProcessResult processes = test::run(sweep(dir + "/processes"), environment);
  EXPECT_EQ(workers.exitCode, 1) << workers.err;
  EXPECT_EQ(processes.exitCode, 1) << processes.err;
  EXPECT_EQ(workers.err, processes.err);
  EXPECT_EQ(test::lines(workers.err).size(), 6u) << "3 progress lines, 3 errors\n" << workers.err;
  for (const char* name : {"light-0.4", "light-0.6", "light-0.8"}) {
    const nlohmann::json manifest =
        nlohmann::json::parse(readText(dir + "/workers/manifests/" + std::string(name) + ".json"));
    EXPECT_EQ(manifest["exit_code"], 3) << name;
    EXPECT_NE(manifest["error"].get<std::string>().find("no GL context"), std::string::npos)
        << manifest["error"];
  }
}

// A worker killed while it renders (as a driver's crash would end it) is started again and
// its variant rendered in the new one; killed again there, the variant fails as a killed
// render process did, and the variants after it still render.
TEST(VariantsWorkers, AKilledWorkerIsRestartedAndItsVariantRetriedOnce) {
  const std::string dir = test::outputDir();
  const std::string file = dir + "/three.variants";
  // The second variant traces a bounce: half a second here, ten times the others, so that
  // it is still rendering when the test kills its worker, on a loaded machine too.
  std::ofstream(file) << "variant before\n  Lamp.intensity = 0.4\n"
                         "variant slow\n  Scene.bounce = TRUE\n  Scene.bounceLights = 16\n"
                         "variant after\n  Lamp.intensity = 0.8\n";
  for (const int kills : {1, 2}) {
    const std::string out = dir + "/killed" + std::to_string(kills);
    const int sweep = test::startProcess({test::ivshadowExe(), "variants", coloured(), file, "-o",
                                          out, "--size", "320x240", "--frames", "3", "--jobs", "1"},
                                         {}, out + ".out", out + ".err");
    ASSERT_GT(sweep, 0);
    // The variant's log is made as it is sent to the worker.
    ASSERT_TRUE(waitUntil([&] { return test::fileExists(out + "/.slow.log"); }));
    std::vector<int> killed;
    for (int k = 0; k < kills; ++k) {
      std::vector<int> workers;
      ASSERT_TRUE(waitUntil([&] {
        workers.clear();
        for (int pid : childrenOf(sweep))
          if (std::find(killed.begin(), killed.end(), pid) == killed.end()) workers.push_back(pid);
        return !workers.empty();
      }));
      ASSERT_EQ(workers.size(), 1u) << "--jobs 1 runs one worker";
      kill(workers[0], SIGKILL);
      killed.push_back(workers[0]);
    }
    const int status = test::waitForProcess(sweep);
    const std::string err = readText(out + ".err");
    const nlohmann::json retried = manifest(out, "slow");
    for (const char* other : {"before", "after"})
      EXPECT_EQ(manifest(out, other)["exit_code"], 0) << other << "\n" << err;
    if (kills == 1) {
      EXPECT_EQ(status, 0) << err;
      EXPECT_EQ(retried["exit_code"], 0) << err;
      const test::ProcessResult alone = test::run(
          {test::ivshadowExe(), "render", coloured(), "-o", dir + "/alone.png", "--size", "320x240",
           "--frames", "3", "--set", "Scene.bounce=TRUE", "--set", "Scene.bounceLights=16"});
      ASSERT_EQ(alone.exitCode, 0) << alone.err;
      EXPECT_TRUE(samePixels(out + "/slow.png", dir + "/alone.png"));
    } else {
      EXPECT_EQ(status, 1) << err;
      EXPECT_EQ(retried["exit_code"], -1);
      EXPECT_NE(err.find(file + ":3: error: variant slow: the render was killed by a signal"),
                std::string::npos)
          << err;
      EXPECT_FALSE(test::fileExists(out + "/slow.png"));
    }
    for (const std::string& name : test::filesIn(out))
      EXPECT_NE(name[0], '.') << "left behind: " << name;
  }
}

// The worker is the sweep's, not a command of the user's: no help or error lists it.
TEST(VariantsWorkers, TheWorkerCommandIsInNoHelpOrList) {
  const test::ProcessResult help = test::run({test::ivshadowExe(), "--help"});
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("variants-merge"), std::string::npos) << help.out;
  EXPECT_EQ(help.out.find("variants-worker"), std::string::npos) << help.out;
  const test::ProcessResult unknown = test::run({test::ivshadowExe(), "rendr"});
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.err.find("expected one of render, "), std::string::npos) << unknown.err;
  EXPECT_EQ(unknown.err.find("variants-worker"), std::string::npos) << unknown.err;
}

}  // namespace
}  // namespace ivshadow
