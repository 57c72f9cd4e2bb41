/* The copy button copies its data-s: the clipboard API where the page is a secure context (as on
   127.0.0.1), else a selected text area and the browser's copy command. `this` is the button. */
var s = this.dataset.s;
var done = function (b) { b.textContent = 'Copied'; };
var b = this;
if (navigator.clipboard && window.isSecureContext) {
  navigator.clipboard.writeText(s).then(function () { done(b); });
} else {
  var t = document.createElement('textarea');
  t.value = s;
  document.body.appendChild(t);
  t.select();
  document.execCommand('copy');
  t.remove();
  done(b);
}
