/* A phone held upright: viser shows its panel as a sheet over the lower part of the canvas, and
   opens it. The page folds it once, as it first appears, to its bar at the foot of the screen (a
   tap on the bar opens it again), so that the canvas, laid out for a phone (view/layout.py: the
   lanes, one diagram under them, the legend above that bar), is seen whole. The sheet is found as
   viser's BottomPanel draws it: a fixed Mantine Paper at the screen's bottom right, whose handle
   is the box with a pointer cursor (backends/_viser.py lists it). Run as the page is parsed. */
(function () {
  'use strict';
  if (window.rigidrelPhone) return;
  window.rigidrelPhone = true;
  var LOOK_MS = 30000;  // stop looking after this long: a wide screen never shows the sheet
  var started = Date.now();
  var look = setInterval(function () {
    var sheet = Array.prototype.find.call(document.querySelectorAll('.mantine-Paper-root'), function (el) {
      return el.style.position === 'fixed' && el.style.bottom === '0px' && el.style.right === '0px';
    });
    if (!sheet) {
      if (Date.now() - started > LOOK_MS) clearInterval(look);
      return;
    }
    var handle = Array.prototype.find.call(sheet.querySelectorAll('div'), function (el) {
      return el.style.cursor === 'pointer';
    });
    if (!handle) return;  // drawn in a moment
    clearInterval(look);
    handle.click();
  }, 100);
})();
