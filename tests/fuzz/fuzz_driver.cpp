// Deterministic mutation driver for the fuzz targets when libFuzzer is not used (any compiler):
//   fuzz_<target> CORPUS_DIR ITERATIONS [SEED] [MAX_SECONDS_PER_INPUT]
// Runs every corpus file as is, then ITERATIONS mutants of them (bit flips, byte changes,
// deletions, duplications, splices and tokens from a dictionary of values that broke parsers
// before: nan, 1e308, 0b101, empty values, duplicate keys ...), seeded, so a run is reproducible.
// A crash (abort, segfault) leaves the input that caused it in fuzz-crash-<target>.bin in the
// working directory; an input slower than MAX_SECONDS_PER_INPUT (default 10) is a hang finding.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

using Bytes = std::vector<std::uint8_t>;

// The input under test, for the crash handler (plain globals: read from a signal handler).
const std::uint8_t* g_current = nullptr;
std::size_t g_current_size = 0;
char g_crash_file[256] = "fuzz-crash.bin";

extern "C" void save_input_and_die(int signal) {
  const int fd = ::open(g_crash_file, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0 && g_current != nullptr) {
    (void)!::write(fd, g_current, g_current_size);
    ::close(fd);
  }
  const char note[] = "fuzz: crash; input saved to the fuzz-crash-*.bin file\n";
  (void)!::write(2, note, sizeof note - 1);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

struct Rng {  // xorshift64*: the same sequence on every platform
  std::uint64_t state;
  std::uint64_t next() {
    state ^= state >> 12;
    state ^= state << 25;
    state ^= state >> 27;
    return state * 2685821657736338717ULL;
  }
  std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(next() % n); }
};

const std::vector<std::string>& dictionary() {
  static const std::vector<std::string> tokens{"nan",
                                               "inf",
                                               "-inf",
                                               "1e308",
                                               "-1e308",
                                               "1e-320",
                                               "-1",
                                               "0",
                                               "-0",
                                               "0b101",
                                               "0x1p3",
                                               "1e20",
                                               "2.1e17",
                                               "99999999999999999999999",
                                               "=",
                                               ",",
                                               "[",
                                               "]",
                                               "[[",
                                               "]]",
                                               "\"",
                                               "'",
                                               "\"\"\"",
                                               "\n",
                                               "\r\n",
                                               "\t",
                                               ".",
                                               "#",
                                               "{",
                                               "}",
                                               "none",
                                               "elastic",
                                               "E=",
                                               "nu=",
                                               "rho=",
                                               "sy=",
                                               "sigma_y=",
                                               "H=",
                                               "E=1e9,E=2e9",
                                               "impact.velocity",
                                               "impact.gap",
                                               "sphere.material",
                                               "substrate.sigma_y",
                                               "solver.max_steps",
                                               "mesh.h_min",
                                               "[grid]",
                                               "[base]",
                                               "[[cases]]",
                                               "[study]",
                                               "max_runs = 1000000",
                                               "case_id",
                                               "status",
                                               "ok",
                                               "\"a,b\"",
                                               "\"\"",
                                               "$Nodes",
                                               "$EndNodes",
                                               "$Elements",
                                               "$EndElements",
                                               "$PhysicalNames",
                                               "$Entities",
                                               "4.1 0 8",
                                               std::string(1, '\0'),
                                               "\xff\xfe",
                                               "\xc3\xa9"};
  return tokens;
}

void mutate(Bytes& b, const std::vector<Bytes>& corpus, Rng& rng) {
  const std::size_t ops = 1 + rng.below(4);
  for (std::size_t op = 0; op < ops; ++op) {
    const std::size_t pos = rng.below(b.size() + 1);
    switch (rng.below(7)) {
      case 0:  // flip one bit
        if (!b.empty()) b[rng.below(b.size())] ^= static_cast<std::uint8_t>(1u << rng.below(8));
        break;
      case 1:  // replace one byte
        if (!b.empty()) b[rng.below(b.size())] = static_cast<std::uint8_t>(rng.next());
        break;
      case 2: {  // delete a run
        const std::size_t n = std::min(b.size() - std::min(pos, b.size()), 1 + rng.below(16));
        b.erase(b.begin() + static_cast<std::ptrdiff_t>(std::min(pos, b.size())),
                b.begin() + static_cast<std::ptrdiff_t>(std::min(pos + n, b.size())));
        break;
      }
      case 3: {  // insert a dictionary token
        const std::string& t = dictionary()[rng.below(dictionary().size())];
        b.insert(b.begin() + static_cast<std::ptrdiff_t>(pos), t.begin(), t.end());
        break;
      }
      case 4: {  // duplicate a chunk (duplicate keys, rows, sections)
        if (b.empty()) break;
        const std::size_t from = rng.below(b.size());
        const std::size_t n = std::min(b.size() - from, 1 + rng.below(64));
        const Bytes chunk(b.begin() + static_cast<std::ptrdiff_t>(from),
                          b.begin() + static_cast<std::ptrdiff_t>(from + n));
        b.insert(b.begin() + static_cast<std::ptrdiff_t>(pos), chunk.begin(), chunk.end());
        break;
      }
      case 5: {  // splice the tail of another corpus entry
        const Bytes& other = corpus[rng.below(corpus.size())];
        const std::size_t from = rng.below(other.size() + 1);
        b.resize(std::min(pos, b.size()));
        b.insert(b.end(), other.begin() + static_cast<std::ptrdiff_t>(from), other.end());
        break;
      }
      default:  // truncate (a killed writer)
        b.resize(std::min(pos, b.size()));
        break;
    }
  }
  if (b.size() > 200000) b.resize(200000);
}

std::vector<Bytes> load_corpus(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());  // directory order is not stable
  std::vector<Bytes> corpus;
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    corpus.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return corpus;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s CORPUS_DIR ITERATIONS [SEED] [MAX_SECONDS_PER_INPUT]\n",
                 argv[0]);
    return 2;
  }
  const std::string name = std::filesystem::path(argv[0]).filename().string();
  std::snprintf(g_crash_file, sizeof g_crash_file, "fuzz-crash-%s.bin", name.c_str());
  for (const int s : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL}) std::signal(s, save_input_and_die);
  const std::vector<Bytes> corpus = load_corpus(argv[1]);
  if (corpus.empty()) {
    std::fprintf(stderr, "%s: empty corpus %s\n", name.c_str(), argv[1]);
    return 2;
  }
  const long iterations = std::atol(argv[2]);
  Rng rng{argc > 3 ? std::strtoull(argv[3], nullptr, 10) | 1ULL : 0x9E3779B97F4A7C15ULL};
  const double max_seconds = argc > 4 ? std::atof(argv[4]) : 10.0;
  double slowest = 0.0;
  auto run = [&](const Bytes& input) {
    g_current = input.data();
    g_current_size = input.size();
    const auto start = std::chrono::steady_clock::now();
    LLVMFuzzerTestOneInput(input.data(), input.size());
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    slowest = std::max(slowest, s);
    if (s > max_seconds) {
      std::fprintf(stderr, "%s: an input took %.1f s (> %.1f s): hang finding\n", name.c_str(), s,
                   max_seconds);
      save_input_and_die(SIGABRT);
    }
  };
  for (const Bytes& input : corpus) run(input);
  for (long i = 0; i < iterations; ++i) {
    Bytes input = corpus[rng.below(corpus.size())];
    mutate(input, corpus, rng);
    run(input);
  }
  std::printf("%s: %zu corpus inputs + %ld mutants, 0 crashes, 0 hangs, slowest input %.3f s\n",
              name.c_str(), corpus.size(), iterations, slowest);
  return 0;
}
