// `quaternia animate` as a user meets it: frame n is byte for byte `quaternia render` of the
// scene --print-frame n prints, ranges and whole films give the same files, a killed run
// started again finishes the film as if nothing had happened, videos hold every frame, and
// bad input is one line, exit code 2 and nothing written.
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <map>
#include <thread>
#include <vector>

#include "cmd/cli_fixture.h"
#include "quaternia/scene/json.h"

extern char** environ;

namespace quaternia {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::readFile;

const std::string kTiny = " --width 32 --height 18 --set render.samples=1 --threads 2";
// Keys (c moves along a smooth curve) at 4 fps: frames 1-5 over one second.
const std::string kKeyed =
    " --set 'animation.keys=[{time = 0, \"fractal.c\" = [-0.2, 0.6, 0.2, 0.2]}, "
    "{time = 0.5, \"fractal.c\" = [-0.3, 0.5, 0.1, 0.3]}, "
    "{time = 1, \"fractal.c\" = [-0.25, 0.55, 0.0, 0.2]}]' --set animation.fps=4";
// A shortcut: the preset's turn through the hidden axis, 6 frames.
const std::string kTurn = " --preset hidden-turn --set animation.fps=3 --set animation.duration=2";

// Every file of a directory by name, with its bytes.
std::map<std::string, std::string> filesOf(const fs::path& directory) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::directory_iterator(directory))
        files[entry.path().filename().string()] = readFile(entry.path());
    return files;
}

bool onPath(const std::string& program) {
    return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

class AnimateCli : public testing::CliFixture {
  protected:
    std::string ok(const std::string& arguments) {
        CommandResult r = run(arguments);
        EXPECT_EQ(r.exitCode, 0) << arguments << ": " << r.err;
        return r.out;
    }
    std::string dir(const std::string& name) const { return (dir_ / name).string(); }
};

TEST_F(AnimateCli, FrameIsTheRenderOfThePrintedScene) {
    for (const auto& [film, frames] :
         {std::pair{kKeyed, std::vector{1, 3, 5}}, std::pair{kTurn, std::vector{2, 6}}}) {
        ok("animate -o " + dir("film") + kTiny + film);
        for (int k : frames) {
            SCOPED_TRACE(k);
            std::string toml = ok("animate --print-frame " + std::to_string(k) + kTiny + film);
            fs::path scene = write("frame.toml", toml);
            ok("render " + scene.string() + " --threads 2 -o " + output());
            std::string name = "frame_00000" + std::to_string(k) + ".png";
            EXPECT_EQ(readFile(dir_ / "film" / name), readFile(output()));
        }
        fs::remove_all(dir_ / "film");
    }
    // Frames differ: the film moves.
    ok("animate -o " + dir("film") + kTiny + kKeyed);
    EXPECT_NE(readFile(dir_ / "film/frame_000001.png"), readFile(dir_ / "film/frame_000003.png"));
}

TEST_F(AnimateCli, RangesAndTheWholeFilmGiveTheSameFiles) {
    Json summary = Json::parse(ok("animate --json -o " + dir("whole") + kTiny + kKeyed));
    EXPECT_EQ(summary["frames_rendered"], 5);
    EXPECT_EQ(summary["frames_skipped"], 0);
    EXPECT_TRUE(summary["frames_per_second"].is_number());
    ok("animate --frames 4-5 -o " + dir("parts") + kTiny + kKeyed);
    // Any number of threads draws the same frames.
    const std::string oneThread = " --width 32 --height 18 --set render.samples=1 --threads 1";
    ok("animate --frames 1-2 -o " + dir("parts") + oneThread + kKeyed);
    ok("animate --frames 3 -o " + dir("parts") + kTiny + kKeyed);
    // Everything there now: the whole film renders nothing.
    summary = Json::parse(ok("animate --json -o " + dir("parts") + kTiny + kKeyed));
    EXPECT_EQ(summary["frames_rendered"], 0);
    EXPECT_EQ(summary["frames_skipped"], 5);
    auto whole = filesOf(dir_ / "whole");
    EXPECT_EQ(whole.size(), 5u);
    EXPECT_EQ(whole, filesOf(dir_ / "parts"));
    // --overwrite renders them again, to the same bytes.
    summary = Json::parse(ok("animate --overwrite --json -o " + dir("parts") + kTiny + kKeyed));
    EXPECT_EQ(summary["frames_rendered"], 5);
    EXPECT_EQ(whole, filesOf(dir_ / "parts"));
}

TEST_F(AnimateCli, AKilledRunStartedAgainFinishesTheFilm) {
    // 12 frames slow enough to be killed in the middle.
    const std::string film = " --width 96 --height 54 --set render.samples=9 --threads 1" + kTurn +
                             " --set animation.duration=4";
    ok("animate -o " + dir("whole") + film);
    const auto whole = filesOf(dir_ / "whole");
    ASSERT_EQ(whole.size(), 12u);

    // A stale temporary that a killed run left for a frame.
    fs::create_directories(dir_ / "killed");
    write("killed/frame_000007.png.tmp-abc123", "partial");
    std::string command =
        std::string(QUATERNIA_BINARY) + " animate -o " + dir("killed") + film + " >/dev/null 2>&1";
    pid_t pid = 0;
    const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
    // exec, so that the pid is quaternia's own
    command = "exec " + command;
    argv[2] = command.c_str();
    ASSERT_EQ(posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ), 0);
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!fs::exists(dir_ / "killed/frame_000002.png") &&
           std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    std::size_t framesAtKill = 0;
    for (const auto& entry : fs::directory_iterator(dir_ / "killed"))
        framesAtKill += entry.path().extension() == ".png";
    EXPECT_GE(framesAtKill, 2u);
    EXPECT_LT(framesAtKill, 12u) << "the run finished before it was killed: nothing was tested";

    Json summary = Json::parse(ok("animate --json -o " + dir("killed") + film));
    EXPECT_EQ(summary["frames_skipped"], int64_t(framesAtKill));
    EXPECT_EQ(filesOf(dir_ / "killed"), whole) << "exactly the files, no temporaries left";
}

TEST_F(AnimateCli, VideosHoldEveryFrameAtTheFrameSize) {
    if (!onPath("ffmpeg") || !onPath("ffprobe")) GTEST_SKIP() << "no ffmpeg";
    // Odd sizes: MP4 and WebM pad to even ones, a GIF keeps them.
    const std::string film = " --width 33 --height 19 --set render.samples=1 --threads 2" + kKeyed;
    ok("animate --frames 2-3 -o " + dir("frames") + film);  // found existing, read back
    for (const auto& [name, size] :
         {std::pair{"film.mp4", "34,20"}, std::pair{"film.webm", "34,20"},
          std::pair{"film.gif", "33,19"}}) {
        SCOPED_TRACE(name);
        Json summary =
            Json::parse(ok("animate --json -o " + dir("frames") + film + " --video " + dir(name)));
        EXPECT_EQ(summary["frames_skipped"].get<int>() + summary["frames_rendered"].get<int>(), 5);
        ASSERT_TRUE(fs::exists(dir_ / name));
        std::string probe =
            "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
            "stream=nb_read_frames,width,height -of csv=p=0 " +
            dir(name) + " > " + dir("probe.txt");
        ASSERT_EQ(std::system(probe.c_str()), 0);
        EXPECT_EQ(readFile(dir_ / "probe.txt"), std::string(size) + ",5\n");
    }
    for (const auto& entry : fs::directory_iterator(dir_))
        EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << entry.path();
}

TEST_F(AnimateCli, BadInputIsOneLineAndWritesNothing) {
    const std::string out = " -o " + dir("frames") + kTiny;
    auto keys = [](const std::string& list) { return " --set 'animation.keys=[" + list + "]'"; };
    const std::string c0 = "\"fractal.c\" = [-0.2, 0.6, 0.2, 0.2]";
    expectUserError(run("animate" + out + keys("{time = 1, " + c0 + "}, {time = 0, " + c0 + "}")),
                    "time order");
    expectUserError(run("animate" + out + keys("{time = 1, " + c0 + "}, {time = 1, " + c0 + "}")),
                    "time order");
    expectUserError(run("animate" + out + keys("{time = 0, \"fractal.cc\" = [0, 0, 0, 0]}")),
                    "unknown parameter 'fractal.cc'");
    expectUserError(run("animate" + out +
                        keys("{time = 0, \"fractal.formula\" = \"z^2 + c\"}, {time = 1, "
                             "\"fractal.formula\" = \"z^3 + c\"}")),
                    "step");
    expectUserError(run("animate" + out + kKeyed + " --set animation.fps=0"), "animation.fps");
    expectUserError(run("animate" + out), "no animation");
    for (const std::string range : {"5-3", "0-2", "1-999", "6", "a-b", "1-", "-2"})
        expectUserError(run("animate" + out + kKeyed + " --frames " + range), "--frames");
    expectUserError(run("animate" + out + kKeyed + " --print-frame 6"), "--print-frame");
    expectUserError(run("animate" + out + kKeyed + " --video " + dir("film.avi")),
                    "unknown video format");
    write("file.toml", "");
    expectUserError(run("animate -o " + dir("file.toml/frames") + kTiny + kKeyed),
                    "cannot create the frame directory");

    // No ffmpeg on PATH: said before any work.
    fs::create_directories(dir_ / "empty.toml");  // a directory the check leaves alone
    std::string path = std::getenv("PATH");
    setenv("PATH", dir("empty.toml").c_str(), 1);
    CommandResult r = run("animate" + out + kKeyed + " --video " + dir("film.mp4"));
    setenv("PATH", path.c_str(), 1);
    expectUserError(r, "ffmpeg");
}

}  // namespace
}  // namespace quaternia
