// The browser check of scripts/site.sh, run in headless Chromium over every page of the site (each
// page in an iframe of one check page, loaded from file:// with --allow-file-access-from-files).
// Per page it reports, as lines between BEGIN-REPORT and END-REPORT:
//   ERROR image-missing PAGE SRC     an <img> that did not load (or has no pixels)
//   ERROR external PAGE URL          a script, stylesheet, image or frame from the network (no CDN)
//   ERROR math PAGE WHAT             a MathML <merror>, TeX pandoc could not convert (span.math),
//                                    TeX left as text ($$, \frac, ...), or a <math> not laid out as MathML
//   ERROR broken-link PAGE HREF      a relative link whose file does not exist, or whose #anchor is
//                                    not an id of the page it points to
//   PAGE page images N math N links N external-links N
// External <a href="https://..."> links are counted, not followed (the check runs offline).
(function () {
  'use strict';
  var lines = [];
  var fileCache = {};
  function report(line) { lines.push(line.replace(/\s+/g, ' ')); }
  function fetchText(url) {  // synchronous: the report must be complete when the DOM is dumped
    if (url in fileCache) return fileCache[url];
    var text = null;
    try {
      var xhr = new XMLHttpRequest();
      xhr.open('GET', url, false);
      xhr.send();
      if (xhr.status === 0 || xhr.status === 200) text = xhr.responseText;
    } catch (e) {
      text = null;
    }
    fileCache[url] = text;
    return text;
  }
  function hasId(doc, id) {
    return !!(doc.getElementById(id) || doc.getElementsByName(id).length);
  }
  function checkPage(frame) {
    var name = frame.title, doc = frame.contentDocument;
    if (!doc || !doc.body) { report('ERROR unreadable ' + name); return; }
    var base = doc.baseURI.split('#')[0];
    var images = 0, maths = 0, links = 0, external = 0;
    doc.querySelectorAll('img').forEach(function (img) {
      images++;
      if (!img.complete || img.naturalWidth === 0) report('ERROR image-missing ' + name + ' ' + img.getAttribute('src'));
    });
    doc.querySelectorAll('script[src], link[href], img[src], iframe[src], object[data], source[src], video[src], audio[src]')
      .forEach(function (e) {
        var u = e.getAttribute('src') || e.getAttribute('href') || e.getAttribute('data') || '';
        if (/^(https?:)?\/\//i.test(u)) report('ERROR external ' + name + ' ' + u);
      });
    doc.querySelectorAll('math').forEach(function (m) {
      maths++;
      var display = frame.contentWindow.getComputedStyle(m).display;
      if (display.indexOf('math') < 0) report('ERROR math ' + name + ' not laid out as MathML (display: ' + display + ')');
    });
    doc.querySelectorAll('merror').forEach(function (m) { report('ERROR math ' + name + ' merror: ' + m.textContent.slice(0, 80)); });
    doc.querySelectorAll('span.math').forEach(function (m) { report('ERROR math ' + name + ' unconverted TeX: ' + m.textContent.slice(0, 80)); });
    // TeX left as text outside code: $$, or a backslash command pandoc did not see as math.
    var walker = doc.createTreeWalker(doc.body, NodeFilter.SHOW_TEXT, null);
    for (var t = walker.nextNode(); t; t = walker.nextNode()) {
      var p = t.parentNode, inCode = false;
      for (; p && p !== doc.body; p = p.parentNode)
        if (/^(CODE|PRE|MATH|SCRIPT|STYLE|ANNOTATION|SVG)$/i.test(p.nodeName)) { inCode = true; break; }
      if (inCode) continue;
      var m = /\$\$|\\(frac|sum|int|mathbf|mathrm|tfrac|sqrt|left|right|cdot|omega|theta|alpha|beta|pi)\b/.exec(t.textContent);
      if (m) report('ERROR math ' + name + ' TeX as text: ' + t.textContent.substr(Math.max(0, m.index - 30), 80));
    }
    doc.querySelectorAll('a[href]').forEach(function (a) {
      var href = a.getAttribute('href');
      if (/^[a-z][a-z0-9+.-]*:/i.test(href)) { external++; return; }
      links++;
      var url = new URL(href, base), file = url.href.split('#')[0], id = decodeURIComponent(url.hash.slice(1));
      if (file === base) {
        if (id && !hasId(doc, id)) report('ERROR broken-link ' + name + ' ' + href + ' (no id ' + id + ' on this page)');
        return;
      }
      var text = fetchText(file);
      if (text === null || (text === '' && /\.html$/.test(file))) { report('ERROR broken-link ' + name + ' ' + href); return; }
      if (id && /\.html$/.test(file)) {
        var target = new DOMParser().parseFromString(text, 'text/html');
        if (!hasId(target, id)) report('ERROR broken-link ' + name + ' ' + href + ' (no id ' + id + ' there)');
      }
    });
    report('PAGE ' + name + ' images ' + images + ' math ' + maths + ' links ' + links + ' external-links ' + external);
  }
  window.addEventListener('load', function () {
    document.querySelectorAll('iframe').forEach(checkPage);
    var pre = document.createElement('pre');
    pre.id = 'report';
    pre.textContent = 'BEGIN-REPORT\n' + lines.join('\n') + '\nEND-REPORT';
    document.body.appendChild(pre);
  });
})();
