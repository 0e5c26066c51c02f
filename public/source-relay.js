// The source relay (public/source-relay.html, SECURITY.md): fetches one URL its same-origin
// parent asks for and posts the bytes back (transferred). Plain script, no build step.
'use strict';
const MAX_BYTES = 256 * 2 ** 20;
addEventListener('message', async (event) => {
  if (event.source !== parent || event.origin !== location.origin || parent === window) return;
  const { id, href } = event.data || {};
  const reply = (message, transfer) => parent.postMessage(message, location.origin, transfer || []);
  if (typeof href !== 'string' || !/^https?:\/\//i.test(href)) {
    reply({ id, error: 'only http(s) addresses are relayed' });
    return;
  }
  try {
    const response = await fetch(href, { credentials: 'omit', referrerPolicy: 'no-referrer', cache: 'no-store' });
    if (!response.ok) throw new Error(`HTTP ${response.status}`);
    const declared = Number(response.headers.get('content-length') || 0);
    if (declared > MAX_BYTES) throw new Error(`${declared} bytes, more than ${MAX_BYTES}`);
    const data = await response.arrayBuffer();
    reply({ id, data }, [data]);
  } catch (error) {
    reply({ id, error: String((error && error.message) || error) });
  }
});
