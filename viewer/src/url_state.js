// The state shown, kept in the page address (#state=N, and &hide=K,... for the paths hidden on a
// page of several), so a link or a reload opens the same moment of the path. The fragment, not
// the query: it changes nothing a file:// page loads.
export function stateFromUrl(count) {
  const match = /(?:^#|&)state=(\d+)/.exec(window.location.hash);
  if (!match) return null;
  const state = Number(match[1]);
  return state < count ? state : null;
}

/// The indices of the paths the address hides (none if it names none).
export function hiddenPathsFromUrl() {
  const match = /(?:^#|&)hide=(\d+(?:,\d+)*)/.exec(window.location.hash);
  return match ? match[1].split(',').map(Number) : [];
}

export function writeStateToUrl(state, hiddenPaths = []) {
  const hash = `#state=${state}${hiddenPaths.length ? `&hide=${hiddenPaths.join(',')}` : ''}`;
  if (window.location.hash !== hash) window.history.replaceState(null, '', hash);
}
