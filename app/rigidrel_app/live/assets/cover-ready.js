/* The server's word to the page's cover (cover.js) that the tab's first page is drawn: sent after
   that page's messages, run by viser's client when it reaches it. */
if (window.rigidrelCover) window.rigidrelCover.ready();
