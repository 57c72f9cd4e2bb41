/* The page's keys and the panel's boxes (added once a page):
   - ← and → stay in a slider that has the focus: stopped on their way up from a slider handle,
     after the slider has used them and before viser's page-wide hotkeys hear them;
   - Enter and Escape in a box give the keys back to the page: once the box has taken the key (a
     number typed is sent as it is typed), the box lets go of the focus, so a clicker's PageDown
     and Space reach the lesson and the clock again. */
if (!window.rigidrelArrows) {
  window.rigidrelArrows = true;
  document.body.addEventListener('keydown', function (e) {
    var t = e.target;
    if ((e.key === 'ArrowLeft' || e.key === 'ArrowRight') && t && t.getAttribute && t.getAttribute('role') === 'slider') {
      e.stopPropagation();
    }
  });
  // heard on the way down (a box may keep Escape to itself), acted on once the box has had it
  document.addEventListener('keydown', function (e) {
    var t = e.target;
    if ((e.key === 'Enter' || e.key === 'Escape') && t && t.tagName === 'INPUT' && !e.isComposing) {
      setTimeout(function () { if (document.activeElement === t) { t.blur(); } }, 0);
    }
  }, true);
}
