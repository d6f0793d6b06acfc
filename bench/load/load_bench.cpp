// impulse-load-bench: does one server hold its tick rate with many awake
// bodies streamed to many subscribers? Starts impulse-server, fills one
// room with awake bodies (a grid drifting without gravity or contacts: every
// body moves every tick, none sleeps), connects the subscribers, and
// measures each second: the server's tick time and rate (Pong stats),
// bytes per second per client, and the server's CPU. With --awake fewer
// than all, the rest are created asleep and the awake ones spin in place
// (still streamed every snapshot, never waking the others); --area-fraction
// gives each subscriber an area of interest and --budget a bandwidth budget
// (docs/networked-play.md). bench/README.md, "Load", has the figures and
// the chart.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

#include "impulse/client/client.h"
#include "impulse/client/commands.h"
#include "load_chart.h"
#include "server_child.h"
#include "subscribers.h"

namespace {

using Clock = std::chrono::steady_clock;

struct LoadOptions {
  int bodies = 10000;
  /// Awake bodies among them; -1: all.
  int awake = -1;
  /// Each subscriber's area of interest: this fraction of the grid, a
  /// vertical strip (subscriber i the (i mod n)-th); 0: the whole room.
  double areaFraction = 0;
  /// Each subscriber's bandwidth budget, bytes a second; 0: none.
  double budget = 0;
  int subscribers = 16;
  double seconds = 10;
  double warmupSeconds = 2;
  double tickHz = 60;
  double snapshotHz = 30;
  int roomThreads = 2;
  std::string encoding = "plain";
  std::string server = IMPULSE_SERVER_BINARY;
  std::string svg;
};

struct Sample {
  double tickMeanMs = 0;
  double tickMaxMs = 0;
  double ticksPerSecond = 0;
  std::uint64_t ticksSkipped = 0;
  std::uint32_t awakeBodies = 0;
  double bytesPerClient = 0;  // per second, mean over the subscribers
  double minBytesPerClient = 0;
  double snapshotsPerClient = 0;
  double serverCpuPercent = 0;  // of one core
};

constexpr double kGridOrigin = -22;
constexpr double kGridSpacing = 0.6;
constexpr const char* kRoom = "load";

int gridColumns(int bodies) { return int(std::ceil(std::sqrt(double(bodies)))); }

// The grid's extent, metres from its origin (it is square).
double gridSide(int bodies) { return kGridSpacing * gridColumns(bodies); }

// A grid of circles with no gravity. All awake: each drifts at the same
// velocity and spin: no contacts, every state field non-zero (the costliest
// body to encode). Fewer awake: one in bodies/awake spins in place and the
// others are made asleep, so none touches another and the awake count holds.
std::vector<impulse::v1::ClientMessage> grid(int bodies, int awake) {
  const int columns = gridColumns(bodies);
  const bool allAwake = awake < 0 || awake >= bodies;
  const int stride = allAwake ? 1 : bodies / std::max(awake, 1);
  std::vector<impulse::v1::ClientMessage> commands;
  for (int i = 0; i < bodies; ++i) {
    impulse::client::SpawnOptions options;
    options.ignoreGravity = true;
    options.isAwake = allAwake || (awake > 0 && i % stride == 0);
    options.angularVelocity = options.isAwake ? 0.7f : 0.0f;
    options.velocityX = allAwake ? 0.25 : 0.0;
    options.velocityY = allAwake ? 0.5 : 0.0;
    const double x = kGridOrigin + kGridSpacing * (i % columns);
    const double y = kGridOrigin + kGridSpacing * (i / columns);
    commands.push_back(impulse::client::spawnCircle({x, y}, 0.2, options));
  }
  return commands;
}

// The room's bounds: the default ones, grown to hold the grid and its drift.
impulse::client::Box roomBounds(int bodies) {
  const double far = std::max(50.0, kGridOrigin + gridSide(bodies) + 20);
  return {{-25, -25}, {far, far}};
}

// Subscriber `index`'s strip of the grid: `fraction` of its width, all its height.
impulse::client::Box areaOf(int index, double fraction, int bodies) {
  const int strips = std::max(1, int(std::lround(1 / fraction)));
  const double width = gridSide(bodies) / strips;
  const double left = kGridOrigin - kGridSpacing / 2 + width * (index % strips);
  return {{left, kGridOrigin - 1}, {left + width, kGridOrigin + gridSide(bodies) + 1}};
}

load::Opening opening(const LoadOptions& options, load::Encoding encoding) {
  return [=](int index) {
    std::vector<impulse::v1::ClientMessage> messages{load::subscriberHello(encoding, index, kRoom)};
    if (options.areaFraction > 0) {
      messages.push_back(impulse::client::setInterestArea(areaOf(index, options.areaFraction, options.bodies)));
    }
    if (options.budget > 0) messages.push_back(impulse::client::setBandwidthBudget(options.budget));
    return messages;
  };
}

void fill(impulse::client::Client& admin, int bodies, int awake) {
  std::vector<std::uint64_t> ids;
  for (auto& command : grid(bodies, awake)) ids.push_back(admin.send(std::move(command)));
  for (const auto id : ids) {
    const auto reply = admin.awaitReply(id, std::chrono::milliseconds(60000));
    if (!reply || !reply->command_result().ok()) {
      throw std::runtime_error("a spawn failed: " +
                               (reply ? reply->command_result().error() : "no reply"));
    }
  }
}

std::vector<Sample> measure(const LoadOptions& options, impulse::client::Client& admin,
                            const load::Subscribers& subscribers,
                            const load::ServerChild& server) {
  std::vector<Sample> samples;
  auto previousTime = Clock::now();
  auto previousStats = admin.ping().stats();
  auto previousTick = admin.ping().server_tick();
  auto previousCounts = subscribers.counts();
  double previousCpu = server.cpuSeconds();
  for (int second = 0; second < int(options.seconds); ++second) {
    std::this_thread::sleep_until(previousTime + std::chrono::seconds(1));
    const auto pong = admin.ping();
    const auto now = Clock::now();
    const auto counts = subscribers.counts();
    const double cpu = server.cpuSeconds();
    const double elapsed = std::chrono::duration<double>(now - previousTime).count();
    Sample sample;
    sample.tickMeanMs = pong.stats().mean_tick_ms();
    sample.tickMaxMs = pong.stats().max_tick_ms();
    sample.ticksPerSecond = double(pong.server_tick() - previousTick) / elapsed;
    sample.ticksSkipped = pong.stats().ticks_skipped() - previousStats.ticks_skipped();
    sample.awakeBodies = pong.stats().awake_bodies();
    double bytes = 0;
    double frames = 0;
    sample.minBytesPerClient = 1e300;
    for (std::size_t i = 0; i < counts.size(); ++i) {
      const double clientBytes = double(counts[i].bytes - previousCounts[i].bytes) / elapsed;
      bytes += clientBytes;
      frames += double(counts[i].frames - previousCounts[i].frames) / elapsed;
      sample.minBytesPerClient = std::min(sample.minBytesPerClient, clientBytes);
    }
    sample.bytesPerClient = bytes / double(counts.size());
    sample.snapshotsPerClient = frames / double(counts.size());
    sample.serverCpuPercent = 100 * (cpu - previousCpu) / elapsed;
    samples.push_back(sample);
    previousTime = now;
    previousStats = pong.stats();
    previousTick = pong.server_tick();
    previousCounts = counts;
    previousCpu = cpu;
  }
  return samples;
}

double mean(const std::vector<Sample>& samples, double Sample::*field) {
  double sum = 0;
  for (const auto& sample : samples) sum += sample.*field;
  return samples.empty() ? 0 : sum / double(samples.size());
}

double maximum(const std::vector<Sample>& samples, double Sample::*field) {
  double result = 0;
  for (const auto& sample : samples) result = std::max(result, sample.*field);
  return result;
}

void report(const LoadOptions& options, const std::vector<Sample>& samples,
            const std::string& sampled, int closed, double longestWithheldSeconds) {
  std::printf("%6s %10s %10s %9s %8s %7s %12s %12s %9s %8s\n", "second", "tick ms", "max ms",
              "ticks/s", "skipped", "awake", "B/s/client", "min B/s", "snaps/s", "CPU %");
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const auto& s = samples[i];
    std::printf("%6zu %10.2f %10.2f %9.1f %8llu %7u %12.0f %12.0f %9.1f %8.1f\n", i + 1,
                s.tickMeanMs, s.tickMaxMs, s.ticksPerSecond,
                static_cast<unsigned long long>(s.ticksSkipped), s.awakeBodies,
                s.bytesPerClient, s.minBytesPerClient, s.snapshotsPerClient, s.serverCpuPercent);
  }
  std::uint64_t skipped = 0;
  for (const auto& s : samples) skipped += s.ticksSkipped;
  std::printf(
      "summary: %d bodies, %d subscribers (%s), %.0f Hz ticks, %.0f Hz snapshots: tick %.2f ms "
      "mean (worst second's max %.2f ms, period %.2f ms), %.1f ticks/s, %llu skipped, "
      "%.0f B/s per client (%.2f Mbit/s), %.1f snapshots/s per client, %.0f %% of a core "
      "(server); %s in a sampled snapshot; %d subscriber(s) dropped\n"
      "streams: %d awake, area %s, budget %s; longest withheld state seen %.2f s\n",
      options.bodies, options.subscribers, options.encoding.c_str(), options.tickHz,
      options.snapshotHz, mean(samples, &Sample::tickMeanMs), maximum(samples, &Sample::tickMaxMs),
      1000 / options.tickHz, mean(samples, &Sample::ticksPerSecond),
      static_cast<unsigned long long>(skipped), mean(samples, &Sample::bytesPerClient),
      mean(samples, &Sample::bytesPerClient) * 8 / 1e6, mean(samples, &Sample::snapshotsPerClient),
      mean(samples, &Sample::serverCpuPercent), sampled.c_str(), closed,
      options.awake < 0 ? options.bodies : options.awake,
      options.areaFraction > 0 ? (std::to_string(options.areaFraction) + " of the grid").c_str() : "whole room",
      options.budget > 0 ? (std::to_string(int(options.budget)) + " B/s").c_str() : "none", longestWithheldSeconds);
}

void chart(const LoadOptions& options, const std::vector<Sample>& samples) {
  std::vector<double> tick, bytes, cpu;
  for (const auto& s : samples) {
    tick.push_back(s.tickMeanMs);
    bytes.push_back(s.bytesPerClient / 1e6);
    cpu.push_back(s.serverCpuPercent);
  }
  const std::string title = std::to_string(options.bodies) + " awake bodies, " +
                            std::to_string(options.subscribers) + " subscribers (" +
                            options.encoding + "), " + std::to_string(int(options.tickHz)) +
                            " Hz";
  const bool written = load::writeChart(
      options.svg, title,
      {{"server tick, mean over each second (ms)", tick, 1000 / options.tickHz, "tick period"},
       {"bytes per second per client (MB/s)", bytes, 0, ""},
       {"server CPU (% of one core)", cpu, 100, "one core"}});
  std::printf(written ? "chart: %s\n" : "cannot write %s\n", options.svg.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  LoadOptions options;
  CLI::App app("Streams a world of awake bodies from one impulse-server to many subscribers "
               "and reports tick time, bytes per second per client and server CPU.",
               "impulse-load-bench");
  app.add_option("--bodies", options.bodies, "awake bodies (default 10000)")
      ->check(CLI::Range(1, 200000));
  app.add_option("--awake", options.awake, "awake bodies among them, the rest asleep (default: all)")
      ->check(CLI::Range(0, 200000));
  app.add_option("--area-fraction", options.areaFraction,
                 "each subscriber's area of interest, this fraction of the grid (default: the whole room)")
      ->check(CLI::Range(0.01, 1.0));
  app.add_option("--budget", options.budget, "each subscriber's bandwidth budget, bytes a second (default: none)")
      ->check(CLI::Range(1000.0, 1.25e8));
  app.add_option("--subscribers", options.subscribers, "subscribers (default 16)")
      ->check(CLI::Range(1, 1000));
  app.add_option("--seconds", options.seconds, "measured seconds (default 10)")
      ->check(CLI::Range(1.0, 3600.0));
  app.add_option("--warmup", options.warmupSeconds, "seconds before measuring (default 2)")
      ->check(CLI::Range(0.0, 600.0));
  app.add_option("--tick-hz", options.tickHz, "server ticks per second (default 60)")
      ->check(CLI::Range(1.0, 1000.0));
  app.add_option("--snapshot-hz", options.snapshotHz, "snapshots per second (default 30)")
      ->check(CLI::Range(0.1, 1000.0));
  app.add_option("--room-threads", options.roomThreads, "the server's stepping threads (default 2)")
      ->check(CLI::Range(1, 64));
  app.add_option("--encoding", options.encoding, "snapshot encoding the subscribers ask for: plain or quantized");
  app.add_option("--server", options.server, "impulse-server binary (default: this build's)");
  app.add_option("--svg", options.svg, "write a chart of the run to this SVG file");
  CLI11_PARSE(app, argc, argv);
  load::Encoding encoding;
  if (!load::parseEncoding(options.encoding, encoding)) {
    std::fprintf(stderr, "impulse-load-bench: --encoding '%s' is not one this build knows (plain, quantized)\n",
                 options.encoding.c_str());
    return 2;
  }
  try {
    load::ServerChild server(
        options.server,
        {"--tick-hz", std::to_string(options.tickHz), "--snapshot-hz",
         // Room for the preset's scenery besides the bench's bodies.
         std::to_string(options.snapshotHz), "--max-bodies", std::to_string(options.bodies + 100),
         "--max-total-bodies", std::to_string(options.bodies + 1000),
         "--max-clients", std::to_string(options.subscribers + 8), "--max-clients-per-address",
         std::to_string(options.subscribers + 8), "--max-commands-per-second", "1000000",
         "--room-threads", std::to_string(options.roomThreads)});
    impulse::client::ConnectOptions connect;
    connect.port = server.port();
    connect.name = "load-admin";
    connect.wantSnapshots = false;
    connect.room = kRoom;
    connect.roomBounds = roomBounds(options.bodies);
    impulse::client::Client admin(connect);
    fill(admin, options.bodies, options.awake);
    // Under a budget subscriber 0 reads every snapshot, for the longest wait.
    load::Subscribers subscribers(server.port(), options.subscribers, opening(options, encoding),
                                  options.budget > 0 ? 1 : 30);
    std::this_thread::sleep_for(std::chrono::duration<double>(options.warmupSeconds));
    const auto samples = measure(options, admin, subscribers, server);
    const std::string sampled =
        encoding == load::Encoding::Quantized
            ? std::to_string(subscribers.sampledQuantizedBytes()) + " bytes of quantized body states"
            : std::to_string(subscribers.sampledBodies()) + " body states";
    report(options, samples, sampled, subscribers.closed(),
           double(subscribers.sampledOldestWithheldTicks()) / options.tickHz);
    if (!options.svg.empty()) chart(options, samples);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "impulse-load-bench: %s\n", error.what());
    return 1;
  }
  return 0;
}
