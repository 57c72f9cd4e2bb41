/* ← and → stay in a slider that has the focus: stopped on their way up from a slider handle, after
   the slider has used them and before viser's page-wide hotkeys hear them (added once a page). */
if (!window.rigidrelArrows) {
  window.rigidrelArrows = true;
  document.body.addEventListener('keydown', function (e) {
    var t = e.target;
    if ((e.key === 'ArrowLeft' || e.key === 'ArrowRight') && t && t.getAttribute && t.getAttribute('role') === 'slider') {
      e.stopPropagation();
    }
  });
}
