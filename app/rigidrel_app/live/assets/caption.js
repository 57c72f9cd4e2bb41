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
  var fit = function () {
    var h = band.style.display === 'none' ? 0 : band.offsetHeight;
    root.style.position = 'fixed'; root.style.left = '0'; root.style.right = '0'; root.style.bottom = '0';
    root.style.height = 'auto'; root.style.top = h + 'px';
  };
  new ResizeObserver(fit).observe(band);
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
    band.style.display = m.shown ? 'block' : 'none';
    fit();
  }, 150);
}
