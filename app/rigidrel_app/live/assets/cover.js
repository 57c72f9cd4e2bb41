/* The page's cover (rigidrel_app/live/cover.py), run as the page is parsed, before any of viser's
   code. The cover is in the page's markup, so it is the first thing painted; it keeps everything
   else in the body hidden (cover.css) until the server says that the tab's first page is sent
   (window.rigidrelCover.ready(), after that page's messages) and the canvas has drawn it; then it
   leaves. If the page cannot reach the server, at first or later, the cover comes back and says so
   in plain words; once the server answers again it says that the scene is loading, until the new
   page is drawn. viser's connection state is read from its viewer's useGui store (found in React's
   fiber tree) and its renders are seen on its three.js scene: both are listed in
   rigidrel_app/backends/_viser.py. */
(function () {
  'use strict';
  if (window.rigidrelCover) return;
  var CONNECT_MS = 5000;  // viser's client started this long ago and no connection yet: unreachable
  var RECONNECT_MS = 2000;  // a connection lost this long ago and not back: unreachable
  var SLOW_MS = 20000;  // no page this long, and viser's connection state not found: said so
  var LOOK_MS = 30000;  // stop looking for viser's viewer after this long
  var cover = document.getElementById('rigidrel-cover');
  var words = document.getElementById('rigidrel-cover-text');
  var html = document.documentElement;
  var host = location.host;
  var still = window.matchMedia('(prefers-reduced-motion: reduce)');
  var started = Date.now();
  var viewer = null;
  var seen = null;  // the connection state last seen
  var connected = false;
  var losses = 0;  // connections lost so far
  var gaveUp = false;  // the cover says the server cannot be reached
  var drawn = false;  // the page is drawn and the cover gone
  var early = false;  // ready() came before viser's client said that it was connected
  var timer = 0;

  function say(text, lost) {
    if (words.textContent !== text) words.textContent = text;
    cover.classList.toggle('rr-cover-lost', !!lost);
  }
  function show(text, lost) {
    drawn = false;
    html.classList.add('rigidrel-covered');
    cover.classList.remove('rr-cover-leaving');
    cover.hidden = false;
    say(text, lost);
  }
  function hide() {
    drawn = true;
    html.classList.remove('rigidrel-covered');
    if (still.matches) {
      cover.hidden = true;
      return;
    }
    cover.classList.add('rr-cover-leaving');  // fades out over the page
    setTimeout(function () { if (drawn) cover.hidden = true; }, 300);
  }
  function state() {
    return viewer ? viewer.useGui.get().websocketState : null;
  }
  function unreachable() {
    gaveUp = true;
    // viser tries again every second while the page has the focus, and not at all without it
    var next = state() === 'inactive' ? 'Click this page to try again.'
      : 'This page keeps trying, and carries on by itself once the server answers.';
    say('Cannot reach the rigidrel server at ' + host + ' \u2014 is it still running? ' + next, true);
  }
  function giveUpIn(ms) {
    clearTimeout(timer);
    timer = setTimeout(function () { if (!connected) unreachable(); }, ms);
  }
  function changed() {
    var now = state();
    if (now === seen) return;
    var first = seen === null;
    seen = now;
    if (now === 'connected') {
      connected = true;
      gaveUp = false;
      clearTimeout(timer);
      if (!drawn) say('Loading the scene\u2026', false);
      if (early) {
        early = false;
        delete cover.dataset.waits;
        window.rigidrelCover.ready();
      }
    } else if (connected) {  // the connection was lost: what the page shows is stale
      connected = false;
      losses += 1;
      early = false;
      show('Lost the connection to the rigidrel server at ' + host + ' \u2014 trying again\u2026', true);
      giveUpIn(RECONNECT_MS);
    } else if (gaveUp) {
      unreachable();  // its advice follows the focus
    } else if (first) {
      giveUpIn(CONNECT_MS);
    }
  }
  function isViewer(value) {
    return !!value && typeof value === 'object' && !!value.useGui
      && typeof value.useGui.get === 'function' && typeof value.useGui.subscribe === 'function';
  }
  function findViewer() {
    var root = document.getElementById('root');
    var key = root && Object.keys(root).find(function (k) { return k.indexOf('__reactContainer$') === 0; });
    var stack = key ? [root[key]] : [];
    var visited = new Set();
    while (stack.length) {
      var fiber = stack.pop();
      if (!fiber || visited.has(fiber)) continue;
      visited.add(fiber);
      var value = fiber.memoizedProps && fiber.memoizedProps.value;
      if (isViewer(value)) return value;
      if (fiber.sibling) stack.push(fiber.sibling);
      if (fiber.child) stack.push(fiber.child);
    }
    return null;
  }
  var looking = setInterval(function () {
    var found = findViewer();
    if (found) {
      clearInterval(looking);
      viewer = found;
      cover.dataset.viewer = 'found';  // seen by the tests
      viewer.useGui.subscribe(changed);
      changed();
      return;
    }
    var waited = Date.now() - started;
    if (!drawn && waited > SLOW_MS) {
      say('Still loading the scene. If nothing changes, check that the rigidrel server at ' + host
        + ' is running, and reload this page (Ctrl+R).', true);
    }
    if (waited > LOOK_MS) {
      clearInterval(looking);
      console.warn('rigidrel: viser\u2019s viewer not found; the page cover cannot follow the connection');
    }
  }, 100);

  /* done() once the canvas has drawn what it was sent: viser renders on demand, so once the
     scene, its labels' glyphs included (rasterized a few milliseconds a frame), are drawn, it stops
     rendering. That is QUIET_MS without a render, seen through three.js's scene.onAfterRender, and
     viser's own note gone (below); or MOST_MS at most (a page that plays at once never stops; its
     first frames draw the glyphs). */
  var QUIET_MS = 200;
  var LEAST_MS = 100;
  var MOST_MS = 4000;
  // viser's own note on software WebGL (a Mantine notification; the panel's a11y script closes it):
  // the cover leaves once it has gone, or it would show through the cover as it fades out
  var VISER_NOTE = 'Software WebGL rendering detected';
  function viserNoteShown() {
    return Array.prototype.some.call(document.querySelectorAll('.mantine-Notification-title'), function (t) {
      return t.textContent.trim() === VISER_NOTE;
    });
  }
  function whenDrawn(done) {
    var scene = viewer && viewer.mutable && viewer.mutable.current && viewer.mutable.current.scene;
    var start = performance.now();
    var last = start;
    var before = scene ? scene.onAfterRender : null;
    if (scene) {
      scene.onAfterRender = function () {
        last = performance.now();
        if (before) return before.apply(this, arguments);
      };
    }
    var check = setInterval(function () {
      var now = performance.now();
      var quiet = now - start > LEAST_MS && now - last > QUIET_MS;
      var noted = quiet && viserNoteShown();
      if (noted) cover.dataset.waits = 'note';  // seen by the tests
      if ((quiet && !noted) || now - start > MOST_MS) {
        if (cover.dataset.waits === 'note') delete cover.dataset.waits;
        clearInterval(check);
        if (scene) scene.onAfterRender = before;
        done();
      }
    }, 50);
  }

  window.rigidrelCover = {
    /* The server's word that the tab's first page is sent: the messages before this one are in
       viser's state now; the cover leaves once the canvas has drawn them. */
    ready: function () {
      var at = losses;
      whenDrawn(function () {
        if (losses !== at) return;  // lost again meanwhile: the server sends its page and this word again
        if (viewer && state() !== 'connected') {
          // The word came over the connection, but viser's store says so later (after the page's
          // first messages, at the first connection or again after a drop; on a loaded machine
          // later still): the cover leaves once it does.
          early = true;
          cover.dataset.waits = 'connection';  // seen by the tests
          return;
        }
        hide();
      });
    },
  };
})();
