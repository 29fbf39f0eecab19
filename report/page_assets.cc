#include "report/page_assets.h"

namespace arbc::report {

const char* const kReportStyle = R"css(
body { font: 14px/1.45 system-ui, -apple-system, "Segoe UI", Helvetica, Arial, sans-serif;
       color: #222; margin: 24px auto; max-width: 1240px; padding: 0 16px; }
h1 { font-size: 22px; margin: 0 0 4px; } h2 { font-size: 17px; margin: 28px 0 8px; }
p.description { color: #555; margin: 0 0 12px; }
tr.broken td { color: #a00; }
dl.header { display: grid; grid-template-columns: max-content auto; gap: 2px 16px; margin: 0; }
dl.header dt { color: #666; } dl.header dd { margin: 0; }
.ok { color: #0a7d32; font-weight: 600; } .bad { color: #c00; font-weight: 600; }
pre { background: #f6f6f6; padding: 8px 10px; overflow-x: auto; font-size: 12.5px; }
table { border-collapse: collapse; font-size: 13px; margin: 4px 0; }
th, td { border-bottom: 1px solid #e3e3e3; padding: 3px 8px; text-align: left;
         vertical-align: top; }
th { background: #f3f3f3; font-weight: 600; }
td.n, th.n { text-align: right; font-variant-numeric: tabular-nums; }
td.zero { color: #bbb; } tr.total td { font-weight: 600; border-top: 2px solid #999; }
tr.feed td:first-child { color: #777; }
div.wide { overflow-x: auto; }
#drops td:first-child, #counters th { white-space: nowrap; }
#drops td:nth-child(2) { min-width: 22em; }
.swatch { display: inline-block; width: 11px; height: 11px; margin-right: 5px;
          vertical-align: -1px; border-radius: 2px; }
.legend span.item { margin-right: 14px; white-space: nowrap; font-size: 13px; }
.note { color: #666; font-size: 12.5px; }
svg.timeline { display: block; max-width: 100%; height: auto; margin: 4px 0;
               font: 12px system-ui, -apple-system, "Segoe UI", Helvetica, Arial, sans-serif; }
svg .axis line { stroke: #ddd; }
svg .axis text { fill: #666; font-size: 11px; text-anchor: middle; }
svg .axis line.end { stroke: #444; stroke-dasharray: 4 3; }
svg text.name { text-anchor: end; fill: #222; } svg text.total { fill: #666; font-size: 11px; }
svg text.heading { font-weight: 600; fill: #333; }
svg rect.stripe { fill: #000; fill-opacity: 0.035; }
svg line.cursor { stroke: #c00; stroke-width: 1; pointer-events: none; }
svg text.cursor-label { fill: #c00; font-size: 11px; pointer-events: none; }
)css";

const char* const kReportScript = R"js(
(function () {
  for (const svg of document.querySelectorAll("svg.timeline")) {
    const x0 = Number(svg.dataset.x0), x1 = Number(svg.dataset.x1);
    const end = Number(svg.dataset.end);
    // Times as the SVG's titles write them (core/time_format.h).
    const unit = svg.dataset.unit, perSecond = Number(svg.dataset.perSecond);
    const decimals = Number(svg.dataset.decimals);
    const line = document.createElementNS(svg.namespaceURI, "line");
    line.setAttribute("class", "cursor");
    line.setAttribute("y1", "0");
    line.setAttribute("y2", String(svg.viewBox.baseVal.height));
    const label = document.createElementNS(svg.namespaceURI, "text");
    label.setAttribute("class", "cursor-label");
    label.setAttribute("y", "10");
    const show = (on) => { line.style.display = label.style.display = on ? "" : "none"; };
    show(false);
    svg.append(line, label);
    svg.addEventListener("mousemove", (e) => {
      const p = new DOMPoint(e.clientX, e.clientY).matrixTransform(svg.getScreenCTM().inverse());
      const on = p.x >= x0 && p.x <= x1;
      show(on);
      if (!on) return;
      line.setAttribute("x1", String(p.x));
      line.setAttribute("x2", String(p.x));
      label.setAttribute("x", String(p.x + 4));
      label.textContent = ((p.x - x0) / (x1 - x0) * end * perSecond).toFixed(decimals) + " " + unit;
    });
    svg.addEventListener("mouseleave", () => show(false));
  }
})();
)js";

}  // namespace arbc::report
