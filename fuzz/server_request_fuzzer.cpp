// The servers' request path (static_file_server.hpp, served_path.hpp): arbitrary bytes as a whole
// request head, and as the target of an otherwise valid GET, answered for a folder that holds a
// page, a script, a link that stays inside, links that lead outside (relative, absolute, to the
// parent folder) and a link loop, beside a secret file. Aborts if an answer ever carries a byte of
// the secret the input did not bring, if a 200 carries anything but a file of the folder, or if a
// file found resolves outside the folder.
#include <cstdlib>
#include <set>

#include "fuzz_input.hpp"
#include "pmdplan/io/servers/served_path.hpp"
#include "pmdplan/io/servers/static_file_server.hpp"

namespace {

constexpr int kPort = 8000;
const std::string kSecret = "PMDPLAN-FUZZ-SECRET-BYTES";
const std::string kPage = "<p>the page</p>";
const std::string kScript = "var inside = 1;";

/// The served folder (scratch/site) and the secret beside it, made once per process.
const std::filesystem::path& servedRoot() {
  static const std::filesystem::path root = [] {
    namespace fs = std::filesystem;
    const fs::path site = pmdplan::fuzz::scratchDirectory() / "site";
    fs::create_directories(site / "sub");
    pmdplan::fuzz::writeScratch("secret.txt", kSecret);
    pmdplan::fuzz::writeScratch("site/index.html", kPage);
    pmdplan::fuzz::writeScratch("site/sub/a.js", kScript);
    const auto link = [&](const fs::path& to, const std::string& name) {
      std::error_code ignored;
      fs::create_symlink(to, site / name, ignored);
    };
    link("index.html", "inside.html");
    link("../secret.txt", "out.txt");
    link(pmdplan::fuzz::scratchDirectory() / "secret.txt", "absolute.txt");
    link("..", "up");
    link("loop", "loop");
    return site;
  }();
  return root;
}

void check(const std::string& input, const std::string& request) {
  const std::string response = pmdplan::staticFileResponse(servedRoot(), request, kPort);
  if (response.rfind("HTTP/1.1 ", 0) != 0) std::abort();  // every request gets an answer
  if (response.find(kSecret) != std::string::npos && input.find(kSecret) == std::string::npos) std::abort();
  if (response.rfind("HTTP/1.1 200 ", 0) == 0) {
    const std::size_t bodyStart = response.find("\r\n\r\n") + 4;
    const std::string body = response.substr(bodyStart);
    if (!body.empty() && body != kPage && body != kScript) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(pmdplan::fuzz::asText(data, size));
  check(input, input);
  check(input, "GET " + input + " HTTP/1.1\r\nHost: 127.0.0.1:8000\r\n\r\n");
  const pmdplan::ServedFile file = pmdplan::openServedFile(servedRoot(), input);
  if (file.status == pmdplan::ServedPathStatus::Found &&
      !pmdplan::liesInside(file.resolved, std::filesystem::canonical(servedRoot())))
    std::abort();
  return 0;
}
