// Reading a crafted capture (docs/security.md): damage built so that every offset looks like the start of a record
// whose length reaches half-way to the end. Each size's time and bytes per second; time should grow with the size,
// not its square (a scan from every offset had taken 13.7 s on 2 MB). Prints figures; never passes or fails on time.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "host/io/capture.hpp"

namespace {

std::string crafted_capture(std::size_t damage_bytes) {
    const std::string path =
        (std::filesystem::temp_directory_path() / ("driftlab_crafted_" + std::to_string(damage_bytes) + ".cap"))
            .string();
    std::ofstream out(path, std::ios::binary);
    out << "driftlab-capture: 1\nport: /dev/null\n\n";
    std::string damage;
    for (std::uint64_t i = 0; damage.size() < damage_bytes; ++i) {
        const std::uint64_t t = 10'000'000 + i;
        const auto len = static_cast<std::uint32_t>((damage_bytes - damage.size()) / 2 + 1);
        damage += 'R';
        for (int b = 0; b < 8; ++b) damage += static_cast<char>((t >> (8 * b)) & 0xFF);
        for (int b = 0; b < 4; ++b) damage += static_cast<char>((len >> (8 * b)) & 0xFF);
    }
    out << damage;
    return path;
}

void BM_ReadCraftedCapture(benchmark::State& state) {
    const auto bytes = static_cast<std::size_t>(state.range(0));
    const std::string path = crafted_capture(bytes);
    for (auto _ : state) {
        driftlab::host::io::CaptureReader reader(path);
        std::size_t records = 0;
        while (reader.next()) ++records;
        benchmark::DoNotOptimize(records);
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(bytes) * static_cast<std::int64_t>(state.iterations()));
    std::filesystem::remove(path);
}
BENCHMARK(BM_ReadCraftedCapture)
    ->Arg(250'000)
    ->Arg(500'000)
    ->Arg(1'000'000)
    ->Arg(2'000'000)
    ->Unit(benchmark::kMillisecond);

}  // namespace
