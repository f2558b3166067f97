// The style of every page `edsc doc` writes: inline, so a page is one file.
#include "doc/render.hpp"

namespace edsc::doc {

std::string_view page_css() {
  return R"css(
:root{--ink:#1f2328;--muted:#656d76;--line:#d8dee4;--soft:#f6f8fa;--accent:#0b5cad;--err:#b42318;--warn:#9a6700;--ok:#1a7f37}
*{box-sizing:border-box}
body{margin:0;color:var(--ink);background:#fff;font:14px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,"Helvetica Neue",Arial,sans-serif}
a{color:var(--accent);text-decoration:none}a:hover{text-decoration:underline}
code,.code,pre{font-family:ui-monospace,SFMono-Regular,Menlo,Consolas,"Liberation Mono",monospace;font-size:12.5px}
header.top{background:linear-gradient(135deg,#0b3d6e,#0b5cad);color:#fff;padding:22px 32px 18px}
header.top a{color:#cfe3ff}
.kicker{font-size:12px;letter-spacing:.06em;text-transform:uppercase;opacity:.85}
h1{margin:6px 0 2px;font-size:28px;line-height:1.2}
.sub{margin:0;font-size:15px;opacity:.9}
.chips{margin-top:12px;display:flex;flex-wrap:wrap;gap:6px}
.chip{display:inline-block;padding:2px 10px;border-radius:999px;background:rgba(255,255,255,.16);border:1px solid rgba(255,255,255,.35);font-size:12.5px}
.chip.err{background:#fde7e7;color:var(--err);border-color:#f5b5b0}.chip.warn{background:#fff4d6;color:var(--warn);border-color:#eed18b}
.chip.ok{background:#e3f6e8;color:var(--ok);border-color:#a6dcb4}.chip.net{background:#fff;color:#0b3d6e;font-weight:600}
nav.toc{position:sticky;top:0;z-index:2;background:#fff;border-bottom:1px solid var(--line);padding:8px 32px;display:flex;flex-wrap:wrap;gap:4px 18px;font-size:13.5px}
[id]{scroll-margin-top:56px}
main{padding:8px 32px 32px;max-width:1400px}
section{margin-top:26px}
h2{font-size:19px;margin:0 0 10px;padding-bottom:4px;border-bottom:2px solid var(--soft)}
h3{font-size:15px;margin:18px 0 6px}
.hint{color:var(--muted);margin:0 0 8px;font-size:13px}
.muted{color:var(--muted)}.note{color:var(--warn);margin:4px 0}.ok{color:var(--ok)}
.cards{display:flex;flex-wrap:wrap;gap:16px}
.card{flex:1 1 380px;border:1px solid var(--line);border-radius:8px;padding:4px 16px 12px;background:#fff}
.card h3{margin:10px 0 6px;color:var(--muted);font-size:12px;text-transform:uppercase;letter-spacing:.06em}
.scroll{overflow-x:auto}
table{border-collapse:collapse;width:100%}
table.kv th{display:none}
table.kv td{padding:5px 8px 5px 0;border-bottom:1px solid var(--soft);vertical-align:top}
table.kv td:first-child{color:var(--muted);width:9.5em;white-space:nowrap}
table.kv td:first-child a{color:var(--muted)}
table.grid{font-size:13px;border:1px solid var(--line)}
table.grid th{background:var(--soft);text-align:left;font-weight:600;padding:6px 8px;border-bottom:1px solid var(--line);white-space:nowrap}
table.grid td{padding:5px 8px;border-top:1px solid #eef1f4;vertical-align:top}
table.grid tbody tr:nth-child(even){background:#fbfcfd}
td.num{font-variant-numeric:tabular-nums;white-space:nowrap}
td.code{white-space:nowrap}
td.flags{color:#5a32a3;font-size:12px;white-space:nowrap}
table.params td:nth-child(2){font-weight:600}
table.params td:nth-child(10){min-width:16em;color:#3d444d}
table.params td:nth-child(9){white-space:nowrap;font-size:12.5px}
figure.map{margin:0 0 22px;border:1px solid var(--line);border-radius:8px;padding:6px 16px 14px;break-inside:avoid}
figure.map h3{margin:8px 0 0}figure.map figcaption p{margin:2px 0 8px;color:var(--muted);font-size:13px}
.maprow{display:flex;flex-wrap:wrap;gap:18px;align-items:flex-start}
.svgbox{flex:0 0 auto;max-width:100%;overflow-x:auto}
svg.bitmap{display:block;max-width:100%;height:auto}
table.legend{width:auto;flex:1 1 320px;font-size:12.5px}
table.legend th{text-align:left;color:var(--muted);font-weight:600;padding:2px 8px 4px 0;border-bottom:1px solid var(--line)}
table.legend td{padding:2px 10px 2px 0;border-bottom:1px solid var(--soft);vertical-align:top}
table.legend tr.pad td{color:var(--muted);font-style:italic}
.sw{display:inline-block;width:12px;height:12px;border-radius:3px;vertical-align:-1px;border:1px solid rgba(0,0,0,.25)}
.sw.c0{background:#cfe3ff}.sw.c1{background:#ffe0b3}.sw.c2{background:#d3f0cf}.sw.c3{background:#f7d2e8}
.sw.c4{background:#e2d8ff}.sw.c5{background:#fff0a6}.sw.c6{background:#c8eeee}.sw.c7{background:#ffd3cc}
.sw.pad{background:repeating-linear-gradient(45deg,#f1f2f4 0 3px,#c9ccd1 3px 5px)}
ul.findings{list-style:none;padding:0;margin:0;border:1px solid var(--line);border-radius:8px;overflow:hidden}
ul.findings li{padding:7px 12px;border-top:1px solid var(--soft);border-left:4px solid #8c959f}
ul.findings li:first-child{border-top:0}
ul.findings li.error{border-left-color:var(--err)}ul.findings li.warning{border-left-color:#d4a72c}
.sev{display:inline-block;min-width:5.2em;font-size:11.5px;font-weight:700;text-transform:uppercase;letter-spacing:.04em;color:var(--muted)}
li.error .sev{color:var(--err)}li.warning .sev{color:var(--warn)}
code.id{color:var(--muted);font-size:11.5px}
.fnote{margin:2px 0 0 5.6em;color:var(--muted);font-size:13px}
details summary{cursor:pointer}details summary h2{display:inline;border:0}
pre.src{counter-reset:ln;background:var(--soft);border:1px solid var(--line);border-radius:8px;padding:8px 0;overflow-x:auto;line-height:1.5}
pre.src>span{display:block;padding:0 12px 0 0;white-space:pre}
pre.src>span::before{counter-increment:ln;content:counter(ln);display:inline-block;width:4.2em;padding-right:1em;text-align:right;color:#9aa3ad;user-select:none}
pre.src>span:target{background:#fff8c5}
pre.src .me{background:#fde7e7}pre.src .mw{background:#fff4d6}pre.src .mn{background:#eef4fb}
footer{color:var(--muted);font-size:12px;padding:16px 32px;border-top:1px solid var(--line)}
table.lib td.err{color:var(--err);font-weight:600}table.lib td.warn{color:var(--warn)}
table.lib tr.group th{background:#eaf1fb;text-align:left;font-size:13.5px;padding:7px 8px}
table.lib th[data-col]{cursor:pointer}
.badge{display:inline-block;font-size:11px;padding:0 6px;border-radius:999px;background:#fde7e7;color:var(--err);margin-left:4px}
.badge.dup{background:#eef1f4;color:var(--muted)}
.callout{border:1px solid #f5b5b0;background:#fff7f6;border-radius:8px;padding:8px 16px;margin:12px 0}
@media print{
  nav.toc,#source,script{display:none}
  header.top{background:none;color:#000;padding:0 0 8px;border-bottom:2px solid #000}
  header.top a{color:#000}.chip{border-color:#999;background:none;color:#000}
  main{padding:0;max-width:none}body{font-size:11px}
  section{break-inside:auto}h2,h3{break-after:avoid}
  table.grid tr,figure.map{break-inside:avoid}
  .scroll,.svgbox{overflow:visible}
  a{color:inherit}
  footer{padding:8px 0}
}
)css";
}

}  // namespace edsc::doc
