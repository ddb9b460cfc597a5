// Added to a copy of viewer.html by viewer_browser.cmake: points at the page
// as a reader would, on a grid over both views, and writes on <body> what the
// page showed: the pieces named on each side (data-pieces-left/right), the
// first seam named (data-seam), and whether a click keeps a piece while the
// pointer moves on (data-pinned).
window.addEventListener('load', function () {
  setTimeout(function () {
    const canvases = document.querySelectorAll('canvas'), info = document.getElementById('info');
    const pieces = [new Set(), new Set()];
    let seam = '', pinnedAt = null;
    function point(c, type, x, y) {
      const r = c.getBoundingClientRect();
      c.dispatchEvent(new PointerEvent(type, { clientX: r.left + x, clientY: r.top + y, bubbles: true, pointerId: 1 }));
    }
    canvases.forEach(function (c, side) {
      const r = c.getBoundingClientRect();
      for (let y = 10; y < r.height; y += 20)
        for (let x = 10; x < r.width; x += 20) {
          point(c, 'pointermove', x, y);
          const piece = /^Piece (\d+)/.exec(info.textContent);
          if (piece) {
            pieces[side].add(piece[1]);
            if (!pinnedAt && side === 1) pinnedAt = [x, y, piece[0]];
          }
          const s = /^Seam (\S+) (between pieces \d+ and \d+|a cut inside piece \d+)length/.exec(info.textContent);
          if (s && !seam) seam = s[1] + ' ' + s[2];
        }
    });
    let pinned = 'no piece';
    if (pinnedAt) {
      const c = canvases[1];
      point(c, 'pointerdown', pinnedAt[0], pinnedAt[1]);
      point(c, 'pointerup', pinnedAt[0], pinnedAt[1]);
      for (let x = 10; x < c.getBoundingClientRect().width; x += 37) point(c, 'pointermove', x, 5);
      pinned = info.textContent.indexOf(pinnedAt[2]) === 0 ? 'kept' : 'lost';
    }
    document.body.dataset.piecesLeft = String(pieces[0].size);
    document.body.dataset.piecesRight = String(pieces[1].size);
    document.body.dataset.seam = seam;
    document.body.dataset.pinned = pinned;
    document.body.dataset.probe = 'done';
  }, 200);
});
