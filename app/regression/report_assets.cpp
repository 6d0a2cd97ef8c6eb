// The HTML report's inline stylesheet and script (app/regression/html_report.h): kept apart from
// the markup so that each stays short. The script only wires the sliders and blink toggles; the
// report reads the same without it.
#include "app/regression/html_report.h"

namespace tumble::app {

const char* report_style() {
    return R"css(
:root { --bad: #c62828; --good: #2e7d32; --ink: #1f2328; --muted: #59636e; --line: #d0d7de; }
* { box-sizing: border-box; }
body { font: 14px/1.45 system-ui, -apple-system, "Segoe UI", Helvetica, Arial, sans-serif;
       color: var(--ink); margin: 0; background: #f6f8fa; }
header { background: #fff; border-bottom: 1px solid var(--line); padding: 16px 24px; }
header h1 { font-size: 20px; margin: 0 0 6px; }
main { padding: 8px 24px 40px; }
code { font: 12px/1.4 ui-monospace, SFMono-Regular, Menlo, Consolas, monospace;
       background: #eef1f4; padding: 1px 4px; border-radius: 4px; word-break: break-all; }
.totals .bad { color: var(--bad); font-weight: 600; }
.totals .good { color: var(--good); font-weight: 600; }
table { border-collapse: collapse; margin: 8px 0; }
th, td { border: 1px solid var(--line); padding: 3px 8px; text-align: left; vertical-align: top; }
th { background: #f0f3f6; font-weight: 600; }
h2.group { font-size: 16px; margin: 24px 0 8px; }
.check { background: #fff; border: 1px solid var(--line); border-left: 6px solid var(--good);
         border-radius: 6px; margin: 12px 0; padding: 10px 16px; }
.check.failed { border-left-color: var(--bad); }
.check h3 { font-size: 16px; margin: 2px 0 6px; }
.check h3 small { color: var(--muted); font-weight: 400; margin-left: 8px; }
.badge { display: inline-block; color: #fff; background: var(--good); border-radius: 4px;
         padding: 0 6px; margin-right: 6px; font-size: 12px; }
.failed .badge { background: var(--bad); }
.summary { margin: 4px 0; }
.details { margin: 4px 0; padding-left: 20px; color: var(--muted); }
.images { display: flex; flex-wrap: wrap; gap: 12px; margin: 8px 0; }
figure { margin: 0; }
figcaption { color: var(--muted); font-size: 12px; }
.pixels, .viewer img { image-rendering: pixelated; display: block; }
.stack { position: relative; display: inline-block; line-height: 0; }
.mask { position: absolute; border: 2px dashed #1565c0; background: rgba(21, 101, 192, 0.12); }
.viewer { position: relative; overflow: hidden; border: 1px solid var(--line); line-height: 0; }
.viewer .over { position: absolute; top: 0; left: 0; height: 100%; overflow: hidden;
                border-right: 2px solid #ff6d00; }
.tools { display: flex; align-items: center; gap: 12px; margin: 6px 0; }
.tools input[type=range] { width: 280px; }
.tools .shown { color: var(--muted); min-width: 160px; }
button { font: inherit; padding: 2px 10px; border: 1px solid var(--line); border-radius: 4px;
         background: #f6f8fa; cursor: pointer; }
.plot { background: #fff; font: 11px sans-serif; margin: 4px 0 10px; display: block; }
.plot .frame { fill: none; stroke: #8c959f; stroke-width: 1; }
.plot .grid { stroke: #eaeef2; stroke-width: 1; }
.plot .band { fill: rgba(46, 125, 50, 0.18); stroke: none; }
.plot .golden { fill: none; stroke: #424a53; stroke-width: 1.5; stroke-dasharray: 5 3; }
.plot .actual { fill: none; stroke: #1565c0; stroke-width: 1.5; }
.plot .out { fill: var(--bad); }
.update code { background: #fff8c5; }
)css";
}

const char* report_script() {
    return R"js(
document.querySelectorAll('.compare').forEach(function (box) {
  var over = box.querySelector('.over'), slider = box.querySelector('input[type=range]');
  var blink = box.querySelector('button.blink'), shown = box.querySelector('.shown');
  var timer = null;
  function show(percent, text) { over.style.width = percent + '%'; shown.textContent = text; }
  function slide() { show(slider.value, 'golden | this run at ' + slider.value + '%'); }
  slider.addEventListener('input', slide);
  blink.addEventListener('click', function () {
    if (timer) { clearInterval(timer); timer = null; blink.textContent = 'blink'; slide(); return; }
    var on = false;
    blink.textContent = 'stop blinking';
    timer = setInterval(function () {
      on = !on;
      show(on ? 100 : 0, on ? 'golden' : 'this run');
    }, 600);
  });
  slide();
});
)js";
}

} // namespace tumble::app
