/* The canvas' size in CSS px and its rendered pixels per CSS px, written into the hidden box
   $box_id as one number (live/canvas_report.py) whenever it changes. */
(function () {
  var last = '';
  setInterval(function () {
    var box = document.getElementById('$box_id');
    var canvas = document.querySelector('canvas[data-engine]');
    if (!box || !canvas || !canvas.clientWidth || !canvas.clientHeight) { return; }
    var h = Math.round(canvas.clientHeight);
    var v = String((Math.round(canvas.clientWidth) * $size_base + h) * $ratio_base
      + Math.round(1000 * canvas.height / canvas.clientHeight));
    if (v === last) { return; }
    last = v;
    var set = Object.getOwnPropertyDescriptor(HTMLInputElement.prototype, 'value').set;
    set.call(box, v);
    box.dispatchEvent(new Event('input', { bubbles: true }));
  }, $poll_ms);
})()
