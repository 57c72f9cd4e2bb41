// Names for the live view's sliders, from outside ipywidgets: its slider handles (noUiSlider,
// role=slider) and their readout boxes carry no accessible name, so a screen reader hears "slider"
// and nothing else. Each gets an aria-label from its row's own label ("V1", "β", "t"), again
// whenever the widgets are drawn anew. Rendered by an invisible widget inside the view's box.
function render({ el }) {
  el.style.display = "none";
  const name = () => {
    const view = el.closest(".rigidrel-live") || el.parentElement;
    if (!view) return;
    view.querySelectorAll(".widget-slider, .widget-hslider").forEach((row) => {
      const label = row.querySelector(".widget-label");
      const text = label ? label.textContent.trim() : "";
      if (!text) return;
      row.querySelectorAll('[role="slider"]').forEach((h) => {
        if (h.getAttribute("aria-label") !== text) h.setAttribute("aria-label", text);
      });
      row.querySelectorAll(".widget-readout").forEach((r) => {
        if (r.getAttribute("aria-label") !== text + ", typed") r.setAttribute("aria-label", text + ", typed");
      });
    });
  };
  let queued = false;
  const observer = new MutationObserver(() => {
    if (queued) return;
    queued = true;
    requestAnimationFrame(() => { queued = false; name(); });
  });
  requestAnimationFrame(() => {
    name();
    const view = el.closest(".rigidrel-live");
    if (view) observer.observe(view, { childList: true, subtree: true });
  });
  return () => observer.disconnect();
}
export default { render };
