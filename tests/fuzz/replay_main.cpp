// Replays fuzz inputs through a target without libFuzzer: every file in the folders (or files)
// given on the command line. Exit 1 on the first input that throws anything but what the target
// accepts; a crash or sanitizer report ends the process. Used by CTest on tests/fuzz/corpus/.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
    std::vector<std::filesystem::path> inputs;
    for (int i = 1; i < argc; ++i) {
        if (std::filesystem::is_directory(argv[i]))
            for (const auto& e : std::filesystem::directory_iterator(argv[i])) inputs.push_back(e.path());
        else
            inputs.emplace_back(argv[i]);
    }
    for (const auto& f : inputs) {
        std::ifstream in(f, std::ios::binary);
        const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        try {
            LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
        } catch (const std::exception& e) {
            std::fprintf(stderr, "FAIL %s: %s\n", f.string().c_str(), e.what());
            return 1;
        }
    }
    std::printf("replayed %zu inputs\n", inputs.size());
    return inputs.empty() ? 1 : 0;
}
