// Costs bounded before the work and outputs that fail cleanly, as a user meets them: a request
// that does not fit in memory is refused at once with one line naming the key (under a real
// address-space limit, as `ulimit -v` sets it, and under --memory-budget); a write that fails
// (a file-size limit, a full device, a directory, a directory the user may not write, also
// when the tests run as root) is one line, exit code 2, no partial file, and an existing file
// of the same name untouched.
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <regex>

#include "cmd/cli_fixture.h"
#include "quaternia/image/png_io.h"
#include "quaternia/render/render_png.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene.h"

namespace quaternia {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::readFile;

// AddressSanitizer reserves terabytes of address space for its shadow memory, so it cannot
// start under an address-space limit: those tests run in the Release build only.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif

// 1.5 GB, as the issue that asked for these checks measured with.
const std::string kAddressLimit = "prlimit --as=1500000000 ";
const std::string kTiny = " --width 24 --height 18 --set render.samples=1 --threads 2";
const std::string kFilm =
    " --preset hidden-turn --set animation.fps=3 --set animation.duration=1 --set "
    "render.samples=1 --threads 2";

class LimitsCli : public testing::CliFixture {
  protected:
    // The command's output under `prefix` (e.g. a prlimit), run through the shell.
    CommandResult runUnder(const std::string& prefix, const std::string& arguments) {
        const std::string command = prefix + QUATERNIA_BINARY + " " + arguments + " >" +
                                    (dir_ / "stdout").string() + " 2>" +
                                    (dir_ / "stderr").string() + " </dev/null";
        const int status = std::system(command.c_str());
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(dir_ / "stdout"),
                readFile(dir_ / "stderr")};
    }
    // The error says the request does not fit, naming `key` and what limited it.
    void expectRefused(const CommandResult& r, const std::string& key, const std::string& limit) {
        expectUserError(r, key);
        EXPECT_NE(r.err.find("of memory, more than the"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(limit), std::string::npos) << r.err;
    }
    // The bytes estimated in a refusal's message ("needs about 1.50 GiB of memory").
    static double estimatedBytes(const std::string& message) {
        std::smatch match;
        if (!std::regex_search(message, match,
                               std::regex("needs about ([0-9.]+) (bytes|KiB|MiB|GiB|TiB)")))
            return -1;
        const std::string units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
        double scale = 1;
        for (const std::string& unit : units) {
            if (unit == match[2]) break;
            scale *= 1024;
        }
        return std::stod(match[1]) * scale;
    }
    // Peak resident bytes of the command (its own process, through wait4).
    static int64_t peakResidentBytes(const std::string& arguments) {
        const pid_t child = ::fork();
        if (child == 0) {
            const std::string command =
                std::string("exec ") + QUATERNIA_BINARY + " " + arguments + " >/dev/null 2>&1";
            ::execl("/bin/sh", "sh", "-c", command.c_str(), (char*)nullptr);
            ::_exit(127);
        }
        int status = 0;
        struct rusage usage {};
        ::wait4(child, &status, 0, &usage);
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return -1;
        return int64_t(usage.ru_maxrss) * 1024;
    }
};

TEST_F(LimitsCli, LargestRenderIsRefusedUnderAnAddressSpaceLimit) {
    if (kAddressSanitizer) GTEST_SKIP() << "AddressSanitizer cannot run under ulimit -v";
    CommandResult r = runUnder(kAddressLimit,
                               "render --width 16384 --height 16384 --set "
                               "render.samples=16 -o " +
                                   output());
    expectRefused(r, "render.width", "ulimit -v");
    EXPECT_GT(estimatedBytes(r.err), 4e9) << "16384^2 pixels of float RGBA alone are 4 GiB";
}

TEST_F(LimitsCli, MeshAtResolution2048IsRefusedUnderAnAddressSpaceLimit) {
    if (kAddressSanitizer) GTEST_SKIP() << "AddressSanitizer cannot run under ulimit -v";
    CommandResult r = runUnder(kAddressLimit, "mesh --resolution 2048 -o " + output("out.stl"));
    expectRefused(r, "mesh.resolution", "ulimit -v");
}

TEST_F(LimitsCli, RenderThatFitsRunsUnderAnAddressSpaceLimit) {
    if (kAddressSanitizer) GTEST_SKIP() << "AddressSanitizer cannot run under ulimit -v";
    CommandResult r = runUnder(kAddressLimit, "render -o " + output() + kTiny);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // The file is the library's render of the same scene.
    Scene scene = defaultScene();
    setParameter(scene, "render.width", int64_t(24));
    setParameter(scene, "render.height", int64_t(18));
    setParameter(scene, "render.samples", int64_t(1));
    RenderOptions options;
    options.threads = 2;
    const std::vector<uint8_t> png = renderPng(scene, options).png;
    EXPECT_EQ(readFile(output()), std::string(png.begin(), png.end()));
}

TEST_F(LimitsCli, MemoryBudgetRefusesEveryCommandBeforeWork) {
    const std::string budget = " --memory-budget 2M";
    expectRefused(run("render --width 4096 --height 4096 -o " + output() + budget), "render.width",
                  "--memory-budget");
    expectRefused(run("plane --width 4096 --height 4096 -o " + output() + budget), "render.width",
                  "--memory-budget");
    expectRefused(run("mesh --resolution 256 -o " + output("out.stl") + budget), "mesh.resolution",
                  "--memory-budget");
    // No frame directory is made for a film that would not fit.
    expectRefused(
        run("animate -o " + output("frames") + kFilm + " --width 2048 --height 2048" + budget),
        "render.width", "--memory-budget");
    // What fits is not refused: a tiny render needs far less than 2 MiB of buffers.
    EXPECT_EQ(run("render -o " + output() + kTiny + budget).exitCode, 0);
}

TEST_F(LimitsCli, BadMemoryBudgetIsOneLineError) {
    for (const std::string value : {"lots", "-1G", "12X", "0", "1e30G"})
        expectUserError(run("render -o " + output() + kTiny + " --memory-budget " + value),
                        "--memory-budget");
    EXPECT_EQ(run("render -o " + output() + kTiny + " --memory-budget 1.5GiB").exitCode, 0);
    EXPECT_EQ(run("render -o " + output() + kTiny + " --memory-budget unlimited").exitCode, 0);
}

TEST_F(LimitsCli, EstimatesBoundWhatTheCommandsTake) {
    if (kAddressSanitizer) GTEST_SKIP() << "AddressSanitizer's shadow memory and redzones";
    // Beyond what a tiny run takes (code, libraries, threads), each command's resident peak is
    // at most its estimate, which its refusal under a tiny budget states.
    const int64_t base = peakResidentBytes("render -o /dev/null" + kTiny);
    ASSERT_GT(base, 0);
    const std::string cases[] = {
        "render --width 2048 --height 1536 --set render.samples=1 --threads 2 -o " + output(),
        "render --width 2048 --height 1536 --set render.samples=1 --set render.bit_depth=16 "
        "--threads 2 --depth " +
            output("depth.png") + " -o " + output(),
        "plane --width 2048 --height 1536 --set plane.kind=basins --threads 2 -o " + output(),
        "mesh --resolution 192 --threads 2 -o " + output("out.stl"),
    };
    for (const std::string& arguments : cases) {
        const double estimate = estimatedBytes(run(arguments + " --memory-budget 1K").err);
        ASSERT_GT(estimate, 0) << arguments;
        const int64_t peak = peakResidentBytes(arguments);
        ASSERT_GT(peak, 0) << arguments;
        EXPECT_LE(double(peak - base), estimate) << arguments;
        // Not so loose that it refuses what would fit: within 3x of what is used.
        EXPECT_LE(estimate, 3.0 * double(peak)) << arguments;
    }
}

TEST_F(LimitsCli, BicomplexEscapeMapsAreCountedBeforeWork) {
    // sin(z) + c builds its duplex components' escape maps (fractal/duplex_escape_map.h) in the
    // render, tens of MiB whatever the image: a budget the tiny image fits but the maps do not
    // is refused naming fractal.formula, before any work, no file written.
    const std::string sine =
        " --set 'fractal.algebra=\"bicomplex\"' --set 'fractal.formula=\"sin(z) + c\"'";
    const std::string bicomplex = kTiny + sine;
    const CommandResult refused = run("render -o " + output() + bicomplex + " --memory-budget 32M");
    expectRefused(refused, "fractal.formula", "--memory-budget");
    EXPECT_FALSE(fs::exists(output()));
    // The plane and the mesh test membership through the same maps.
    expectRefused(run("plane -o " + output() + bicomplex +
                      " --set 'plane.kind=\"slice\"' --memory-budget 32M"),
                  "fractal.formula", "--memory-budget");
    expectRefused(run("mesh --resolution 16 --threads 2 -o " + output("out.stl") + sine +
                      " --memory-budget 32M"),
                  "fractal.formula", "--memory-budget");
    EXPECT_FALSE(fs::exists(output()));
    EXPECT_FALSE(fs::exists(output("out.stl")));
    // The quaternion scene at that budget is not refused.
    EXPECT_EQ(run("render -o " + output() + kTiny + " --memory-budget 32M").exitCode, 0);
    if (kAddressSanitizer) return;  // its shadow memory and redzones
    // The stated estimate bounds what the maps take beyond the tiny quaternion render, and is
    // not so loose that it refuses what would fit.
    const double estimate = estimatedBytes(refused.err);
    const int64_t base = peakResidentBytes("render -o /dev/null" + kTiny);
    const int64_t peak = peakResidentBytes("render -o /dev/null" + bicomplex);
    ASSERT_GT(estimate, 0);
    ASSERT_GT(base, 0);
    ASSERT_GT(peak, 0);
    EXPECT_LE(double(peak - base), estimate);
    EXPECT_LE(estimate, 3.0 * double(peak - base));
}

// --- Write failures ---

class WriteFailureCli : public LimitsCli {
  protected:
    // The command, which writes `name`, under a file-size limit (ulimit -f) of `limit` bytes,
    // with an existing file of that name: one line, exit 2, the old file as it was, no
    // temporary.
    void expectFileSizeLimitReported(const std::string& arguments, const std::string& name,
                                     int limit = 20000) {
        SCOPED_TRACE(arguments);
        write(name, "old contents");
        CommandResult r = runUnder("prlimit --fsize=" + std::to_string(limit) + " ", arguments);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_NE(r.err.find("File too large"), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(readFile(dir_ / name), "old contents");
        for (const auto& entry : fs::recursive_directory_iterator(dir_))
            EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
                << "left behind: " << entry.path();
    }
};

TEST_F(WriteFailureCli, FileSizeLimitIsOneLineAndKeepsTheOldFile) {
    const std::string big = " --width 400 --height 300 --set render.samples=1 --threads 2";
    expectFileSizeLimitReported("render -o " + output() + big, "out.png");
    expectFileSizeLimitReported("plane -o " + output() + " --width 800 --height 600", "out.png");
    expectFileSizeLimitReported("mesh --resolution 48 -o " + output("out.stl"), "out.stl");
    expectFileSizeLimitReported("mesh --resolution 48 -o " + output("out.ply"), "out.ply");
    // A film: a frame that does not fit (rendered again, --overwrite, over an existing one).
    fs::create_directory(dir_ / "frames");
    expectFileSizeLimitReported(
        "animate --overwrite -o " + output("frames") + kFilm + " --width 640 --height 360",
        "frames/frame_000001.png");
    // A video whose container ffmpeg cannot finish, from frames that are there already.
    if (std::system("command -v ffmpeg >/dev/null 2>&1") == 0) {
        fs::remove_all(dir_ / "frames");
        const std::string film =
            "animate -o " + output("frames") + kFilm + " --width 160 --height 90";
        ASSERT_EQ(run(film).exitCode, 0);
        expectFileSizeLimitReported(film + " --video " + output("film.mp4"), "film.mp4", 2000);
    }
}

TEST_F(WriteFailureCli, FullDeviceIsOneLineErrorAndStaysADevice) {
    CommandResult r = run("render -o /dev/full" + kTiny);
    expectUserError(r, "cannot write '/dev/full': No space left on device");
    struct stat device;
    ASSERT_EQ(::stat("/dev/full", &device), 0);
    EXPECT_TRUE(S_ISCHR(device.st_mode));
    // Standard output on a full device: the answer is lost, and the exit code says so.
    const std::string command = std::string(QUATERNIA_BINARY) +
                                " orbit --c 0.1 --json >/dev/full 2>" + (dir_ / "stderr").string();
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2);
    const std::string err = readFile(dir_ / "stderr");
    EXPECT_EQ(err, "quaternia: error: cannot write standard output: No space left on device\n");
}

TEST_F(WriteFailureCli, DirectoryAsOutputIsOneLineError) {
    fs::create_directory(dir_ / "out.png");
    CommandResult r = run("render -o " + output() + kTiny);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, "quaternia: error: cannot write '" + output() + "': Is a directory\n");
    EXPECT_TRUE(fs::is_directory(dir_ / "out.png"));
    EXPECT_TRUE(fs::is_empty(dir_ / "out.png"));
}

TEST_F(WriteFailureCli, UnwritableDirectoryIsRefusedAlsoForRoot) {
    // Root may write anywhere, so as root (CI) the command runs as user nobody, as a user
    // without that power would; the directory is the user's to read, not to write.
    fs::permissions(dir_, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                              fs::perms::others_read | fs::perms::others_exec);
    const fs::path locked = dir_ / "locked";
    fs::create_directory(locked);
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                fs::perms::group_exec | fs::perms::others_read |
                                fs::perms::others_exec);
    const std::string asUser =
        ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
    for (const std::string& arguments : {"render" + kTiny + " -o ", "plane" + kTiny + " -o ",
                                         std::string("mesh --resolution 16 -o ")}) {
        const std::string target =
            (locked / (arguments.starts_with("mesh") ? "out.stl" : "out.png")).string();
        CommandResult r = runUnder(asUser, arguments + target);
        EXPECT_EQ(r.exitCode, 2) << arguments << r.err;
        EXPECT_EQ(r.err, "quaternia: error: cannot write '" + target + "': Permission denied\n")
            << arguments;
    }
    EXPECT_TRUE(fs::is_empty(locked));
    fs::permissions(locked, fs::perms::owner_all);
}

}  // namespace
}  // namespace quaternia
