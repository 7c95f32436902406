// store.js — the front end's state in one object and a tiny change notification: modules
// read `store.state`, change it with `store.set({...})`, and listen with `store.on(key, fn)`
// (fn runs after any set() that touched that key; '*' for every change).

export function createStore(initial) {
  const listeners = new Map();
  const store = {
    state: { ...initial },
    set(patch) {
      Object.assign(store.state, patch);
      const keys = Object.keys(patch);
      const called = new Set();
      for (const key of [...keys, '*']) {
        for (const fn of listeners.get(key) || []) {
          if (called.has(fn)) continue;
          called.add(fn);
          fn(store.state, keys);
        }
      }
    },
    on(keys, fn) {
      for (const key of [].concat(keys)) {
        if (!listeners.has(key)) listeners.set(key, []);
        listeners.get(key).push(fn);
      }
    },
  };
  return store;
}

// Runs async tasks one after another (a session runs one operation at a time: the server
// answers 409 to a second one).
export function createQueue() {
  let tail = Promise.resolve();
  let pending = 0;
  return {
    run(task) {
      ++pending;
      const result = tail.then(task);
      tail = result.catch(() => {}).finally(() => --pending);
      return result;
    },
    get pending() {
      return pending;
    },
    idle() {
      return tail;
    },
  };
}
