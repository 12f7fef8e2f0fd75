// The HTML report opened in a real browser (headless Chromium, Debian `chromium`): with a navigation section, every
// section and figure renders, no image is broken and nothing is written to the console (docs/nav.md §Report).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "e2e_support.hpp"

namespace driftlab::e2e {
namespace {

const char* kChromium = "/usr/bin/chromium";

// Put before the page's own content: every error and console message is kept; after load, what rendered is written
// into the page as JSON, where --dump-dom shows it.
const char* kProbeHead = R"(<script>
window.__problems = [];
window.addEventListener('error', e => window.__problems.push('error: ' + (e.message || e.target.outerHTML)), true);
for (const k of ['error', 'warn']) { const f = console[k]; console[k] = (...a) => { window.__problems.push(k + ': ' + a.join(' ')); f(...a); }; }
</script>)";
const char* kProbeTail = R"(<script>
window.addEventListener('load', () => {
  const r = {sections: [...document.querySelectorAll('h2')].map(e => e.textContent), figures: 0, empty_figures: 0,
             images: 0, broken_images: 0, problems: window.__problems};
  for (const s of document.querySelectorAll('figure svg')) {
    r.figures++;
    const b = s.getBoundingClientRect();
    if (b.width < 50 || b.height < 50 || s.querySelectorAll('path').length === 0) r.empty_figures++;
  }
  for (const i of document.querySelectorAll('img')) { r.images++; if (!i.complete || i.naturalWidth === 0) r.broken_images++; }
  const pre = document.createElement('pre'); pre.id = 'driftlab-probe'; pre.textContent = JSON.stringify(r);
  document.body.appendChild(pre);
});
</script>)";

TEST(ReportBrowser, TheNavigationReportRendersEverySectionAndFigureWithoutAnError) {
    if (!std::filesystem::exists(kChromium)) GTEST_SKIP() << "chromium is not installed (scripts/setup.sh installs it)";
    TempDir dir("report_browser");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "900", "--period", "0.2", "--seed", "2", "-o", dir.file("rest.csv")},
                           dir.path())
                  .exit_code,
              0);
    ASSERT_EQ(run_driftlab({"hil", "--trajectory", "stop-and-go", "--rest-before", "10", "--duration", "300",
                            "--period", "0.2", "--seed", "3", "-o", dir.file("sg.csv")},
                           dir.path())
                  .exit_code,
              0);
    const SplitRun nav = run_driftlab_split({"nav", dir.file("sg.csv"), "--truth", dir.file("sg.truth.csv"),
                                             "--fit-from", dir.file("rest.csv"), "--aid", "zupt", "--json"},
                                            dir.path());
    ASSERT_EQ(nav.exit_code, 0) << nav.err;
    std::ofstream(dir.file("nav.json")) << nav.out;
    const RunResult report = run_driftlab(
        {"report", dir.file("rest.csv"), "--nav", dir.file("nav.json"), "-o", dir.file("report.html")}, dir.path());
    ASSERT_EQ(report.exit_code, 0) << report.output;

    std::stringstream page;
    page << std::ifstream(dir.file("report.html")).rdbuf();
    std::string html = page.str();
    html.insert(html.find("<head>") + 6, kProbeHead);
    html.insert(html.rfind("</body>"), kProbeTail);
    std::ofstream(dir.file("probe.html")) << html;
    const pid_t pid = spawn_program(kChromium,
                                    {"--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                                     "--no-first-run", "--user-data-dir=" + dir.file("profile"),
                                     "--virtual-time-budget=10000", "--dump-dom", "file://" + dir.file("probe.html")},
                                    dir.file("chromium.err"), dir.file("dom.html"));
    const RunResult browser = wait_child(pid, dir.file("chromium.err"));
    ASSERT_EQ(browser.exit_code, 0) << browser.output;
    std::stringstream dom;
    dom << std::ifstream(dir.file("dom.html")).rdbuf();
    const std::string d = dom.str();
    const auto at = d.find("<pre id=\"driftlab-probe\">");
    ASSERT_NE(at, std::string::npos) << "the page's load handler did not run:\n" << browser.output;
    const auto from = d.find('>', at) + 1;
    std::string text = d.substr(from, d.find("</pre>", from) - from);
    for (const auto& [entity, ch] :
         {std::pair<std::string, std::string>{"&quot;", "\""}, {"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}})
        for (std::size_t p; (p = text.find(entity)) != std::string::npos;) text.replace(p, entity.size(), ch);
    const nlohmann::json r = nlohmann::json::parse(text);
    const std::vector<std::string> sections = r["sections"];
    for (const char* want : {"Turn-on drift", "Whiteness", "Allan analysis", "Figures", "Navigation"}) {
        bool seen = false;
        for (const auto& s : sections) seen = seen || s.find(want) != std::string::npos;
        EXPECT_TRUE(seen) << want << " in " << r["sections"].dump();
    }
    // Fig. 3 and 4 per channel (4 channels), the Allan deviations, and the three navigation figures.
    EXPECT_GE(r["figures"].get<int>(), 4 * 2 + 3) << r.dump();
    EXPECT_EQ(r["empty_figures"], 0) << r.dump();
    EXPECT_EQ(r["broken_images"], 0) << r.dump();
    EXPECT_TRUE(r["problems"].empty()) << r.dump();
    EXPECT_EQ(browser.output.find("Uncaught"), std::string::npos) << browser.output;
}

}  // namespace
}  // namespace driftlab::e2e
