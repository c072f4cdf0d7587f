// The state shown, kept in the page address (#state=N), so a link or a reload opens the same
// moment of the path. The fragment, not the query: it changes nothing a file:// page loads.
export function stateFromUrl(count) {
  const match = /(?:^#|&)state=(\d+)/.exec(window.location.hash);
  if (!match) return null;
  const state = Number(match[1]);
  return state < count ? state : null;
}

export function writeStateToUrl(state) {
  const hash = `#state=${state}`;
  if (window.location.hash !== hash) window.history.replaceState(null, '', hash);
}
