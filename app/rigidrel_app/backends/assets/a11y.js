/* Names and contrast for viser's panel, from outside (added once a page; everything it reaches in
   viser's client is listed in rigidrel_app/backends/_viser.py). viser's sliders, the number boxes
   beside them, a few icon buttons and some text boxes carry no accessible name, and its labels are
   Mantine's "dimmed" grey (3.3:1 on white). A screen reader then hears "slider" with no name. So:
   - every slider, box and unnamed button gets an aria-label from its control's own label (or, for
     an icon button, from what its icon means), again whenever viser draws the panel anew;
   - the keyboard's focus is always a ring;
   - the dimmed grey and the grey buttons are darkened in the light theme, the dimmed grey lightened
     and the filled buttons' text white in the dark one: 4.5:1 or more everywhere;
   - viser's note "Software WebGL rendering detected", which never closes by itself and covers the
     top of the canvas, is closed. */
if (!window.rigidrelA11y) (function () {  // a scope of its own: a page's global `name` is window.name
  window.rigidrelA11y = true;
  var ICONS = {
    'list-search': 'Commands (Ctrl+K)',
    'adjustments': 'Configuration and diagnostics',
    'arrow-back': 'Back to the controls',
    'x': 'Close this message',
    'share': 'Share',
  };
  var SOFTWARE_WEBGL = 'Software WebGL rendering detected';
  var named = function (el) {
    return (el.getAttribute('aria-label') || '').trim() || (el.getAttribute('aria-labelledby') || '').trim()
      || (el.id && document.querySelector('label[for="' + CSS.escape(el.id) + '"]'));
  };
  var rowLabel = function (el) {
    for (var up = el.parentElement, k = 0; up && k < 6; up = up.parentElement, k++) {
      var label = up.querySelector('label');
      if (label && label.textContent.trim()) return label.textContent.trim();
    }
    return '';
  };
  var iconName = function (el) {
    var svg = el.querySelector('svg[class*="tabler-icon-"]');
    if (!svg) return el.classList.contains('mantine-CloseButton-root') ? ICONS.x : '';
    var m = /tabler-icon-([a-z0-9-]+)/.exec(svg.getAttribute('class'));
    if (!m) return '';
    return ICONS[m[1]] || m[1].replace(/-/g, ' ');
  };
  var name = function () {
    document.querySelectorAll('[role="slider"]').forEach(function (el) {
      if (named(el)) return;
      var root = el.closest('.mantine-Slider-root[id]');
      var own = root && document.querySelector('label[for="' + CSS.escape(root.id) + '"]');
      var label = own ? own.textContent.trim() : rowLabel(el);
      if (own && (label === 'log scale' || label === '')) {  // its number's name is on the text box above it
        var above = '';
        for (var up = own.parentElement, k = 0; up && k < 8 && !above; up = up.parentElement, k++) {
          var before = up.previousElementSibling && up.previousElementSibling.querySelector('label');
          above = before ? before.textContent.trim() : '';
        }
        label = above + (label ? ', ' + label : above ? ', slider' : '');
      }
      if (label) el.setAttribute('aria-label', label);
    });
    document.querySelectorAll('input:not([type="hidden"]), textarea').forEach(function (el) {
      if (named(el) || el.closest('label')) return;
      var label = rowLabel(el);
      if (!label && el.closest('.mantine-Paper-root')) {  // the exported pages' playback bar: its time and speed
        label = el.getAttribute('role') === 'combobox' ? 'Playback speed' : 'Playback time';
      }
      if (!label) return;
      el.setAttribute('aria-label', el.classList.contains('mantine-NumberInput-input') ? label + ', typed' : label);
    });
    document.querySelectorAll('button, [role="button"]').forEach(function (el) {
      if (named(el) || el.textContent.trim()) return;
      var label = iconName(el);
      if (label) el.setAttribute('aria-label', label);
    });
    // viser's note that WebGL runs in software never closes by itself and covers the lanes' titles,
    // in a hall too: closed (the page says it on the console instead)
    document.querySelectorAll('.mantine-Notification-root').forEach(function (el) {
      var title = el.querySelector('.mantine-Notification-title');
      var close = el.querySelector('.mantine-Notification-closeButton, .mantine-CloseButton-root');
      if (!title || title.textContent.trim() !== SOFTWARE_WEBGL || !close || el.dataset.rigidrelClosed) return;
      el.dataset.rigidrelClosed = '1';
      console.info('rigidrel: ' + SOFTWARE_WEBGL + ' (the note viser shows is closed: it covered the canvas)');
      close.click();
    });
  };
  var queued = false;
  new MutationObserver(function () {
    if (queued) return;
    queued = true;
    requestAnimationFrame(function () { queued = false; name(); });
  }).observe(document.body, { childList: true, subtree: true });
  name();
  var style = document.createElement('style');
  style.id = 'rigidrel-a11y';
  style.textContent = 'html[data-mantine-color-scheme="light"] p[unselectable="off"] { color: #5c636a !important; }'
    + ' html[data-mantine-color-scheme="light"] .mantine-Button-root { --mantine-color-gray-filled: #5c636a;'
    + ' --mantine-color-gray-filled-hover: #495057; }'
    + ' html[data-mantine-color-scheme="dark"] p[unselectable="off"] { color: #a6a7ab !important; }'
    + ' html[data-mantine-color-scheme="dark"] .mantine-Button-root:is(:not([data-variant]), [data-variant="filled"]) { --button-color: #ffffff !important; }'
    // the keyboard's place always drawn as a ring (Mantine's inputs only recolour their border)
    + ' :is(input, textarea, button, a, [role], [tabindex]):focus-visible { outline: 2px solid #0072B2 !important; outline-offset: 1px; }'
    + ' html[data-mantine-color-scheme="dark"] :is(input, textarea, button, a, [role], [tabindex]):focus-visible { outline-color: #4DBFFF !important; }';
  document.head.appendChild(style);
})();
