/* The caption band over the lanes and the page's own style sheet (see live/controls.py). Run from
   an image's onerror (viser's HTML element runs no <script>); `this` is that image, whose data-key
   is the session's localStorage key. */
window.rigidrelCaptionKey = this.dataset.key;
if (!window.rigidrelCaption) {
  window.rigidrelCaption = true;
  var band = document.createElement('div');
  band.id = 'rigidrel-caption';
  band.style.display = 'none';
  document.body.appendChild(band);
  var root = document.getElementById('root');
  // The band's height does not follow its text: it is what the viewport has beyond the canvas
  // height the diagrams need (the server's `reserve`), at least a title and two lines, at most
  // the server's share of the viewport (`share`). So every step of a lesson leaves the canvas the same size (a step change
  // never resizes it, so it is never drawn for one size and shown at another), and a long caption
  // scrolls inside its band: a shadow at its foot says there is more, the wheel or ↑ ↓ read it.
  var reserve = 0, share = 0.25;
  band.setAttribute('role', 'region');
  band.setAttribute('aria-label', 'Step caption');
  var fit = function () {
    var shown = band.style.display !== 'none';
    if (shown) {
      var room = Math.min(window.innerHeight - reserve, share * window.innerHeight);
      band.style.height = Math.max(room, 88) + 'px';
    }
    var more = shown && band.scrollHeight > band.clientHeight + 2;
    band.classList.toggle('rr-more', more && band.scrollTop + band.clientHeight < band.scrollHeight - 2);
    if (more) band.setAttribute('tabindex', '0'); else band.removeAttribute('tabindex');
    var h = shown ? band.offsetHeight : 0;
    root.style.position = 'fixed'; root.style.left = '0'; root.style.right = '0'; root.style.bottom = '0';
    root.style.height = 'auto'; root.style.top = h + 'px';
  };
  new ResizeObserver(fit).observe(band);
  window.addEventListener('resize', fit);
  band.addEventListener('scroll', fit);
  // a clicker's keys and the lesson's arrows move the lesson, not the band's text, when the band has
  // the focus (the event goes on to the page's keys)
  band.addEventListener('keydown', function (e) {
    if (['PageUp', 'PageDown', 'ArrowLeft', 'ArrowRight', ' '].indexOf(e.key) >= 0) e.preventDefault();
  });
  // What the canvas shows, in words, for a screen reader: announced politely when the server
  // says it (a scene, figure, frame or step change, or key D), never every frame. Seen by no one.
  var said = document.createElement('div');
  said.id = 'rigidrel-said';
  said.setAttribute('role', 'status');
  said.setAttribute('aria-live', 'polite');
  said.setAttribute('aria-atomic', 'true');
  said.style.cssText = 'position:absolute;width:1px;height:1px;margin:-1px;padding:0;border:0;'
    + 'overflow:hidden;clip:rect(0 0 0 0);clip-path:inset(50%);white-space:normal';
  document.body.appendChild(said);
  setInterval(function () {
    var v = localStorage.getItem(window.rigidrelCaptionKey + '-said');
    if (v === null) return;
    localStorage.removeItem(window.rigidrelCaptionKey + '-said');
    var m = JSON.parse(v);
    said.textContent = '';  // the same words again (key D) are announced again
    setTimeout(function () { said.textContent = m.text; }, 50);
  }, 150);
  setInterval(function () {
    var v = localStorage.getItem(window.rigidrelCaptionKey);
    if (v === null) return;
    localStorage.removeItem(window.rigidrelCaptionKey);
    var m = JSON.parse(v);
    var sheet = document.getElementById('rigidrel-page-style');
    if (!sheet) { sheet = document.createElement('style'); sheet.id = 'rigidrel-page-style'; document.head.appendChild(sheet); }
    sheet.textContent = m.style;
    band.innerHTML = m.html;
    band.scrollTop = 0;
    reserve = m.reserve || 0;
    share = m.share || share;
    band.style.display = m.shown ? 'block' : 'none';
    fit();
  }, 150);
}
