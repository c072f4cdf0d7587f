// Small DOM helpers shared by the panels.
export function byId(id) {
  const element = document.getElementById(id);
  if (!element) throw new Error(`the page has no #${id}`);
  return element;
}

export function element(tag, attributes = {}, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) {
    if (key === 'class') node.className = value;
    else node.setAttribute(key, value);
  }
  for (const child of children) node.append(child);
  return node;
}

/// A horizontal meter: `fraction` in [0, 1] from the left, or, when centred, [-1, 1] from the middle.
export function meter(centred) {
  const bar = element('span');
  const outer = element('div', { class: centred ? 'meter centred' : 'meter' }, bar);
  return {
    node: outer,
    set(fraction) {
      const f = Math.max(centred ? -1 : 0, Math.min(1, fraction));
      if (centred) {
        bar.style.left = `${50 + Math.min(0, f) * 50}%`;
        bar.style.width = `${Math.abs(f) * 50}%`;
      } else {
        bar.style.left = '0';
        bar.style.width = `${f * 100}%`;
      }
    },
  };
}

export function signed(value, digits) {
  const text = value.toFixed(digits);
  const zero = Number(text) === 0;  // no "-0.000"
  return zero ? `+${(0).toFixed(digits)}` : (value > 0 ? '+' : '') + text;
}
