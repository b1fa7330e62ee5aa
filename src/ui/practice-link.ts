/**
 * `?exercise=ID-or-URL`: a link that opens an exercise in the Practice tab. An id names a built-in
 * exercise; anything else is the URL of an instructor's exercise file (JSON, see docs/practice.md),
 * whose reference solution and fixture files are fetched beside it.
 */
import { type Exercise, parseExercise } from '../core/practice/exercise.js';
import { findExercise } from '../core/practice/exercises.js';

export async function exerciseFromLink(value: string): Promise<Exercise> {
  const builtIn = findExercise(value);
  if (builtIn) return builtIn;
  const url = new URL(value, location.href);
  const doc: unknown = await (await fetchOk(url)).json().catch(() => {
    throw new Error(`${url.pathname} is not JSON`);
  });
  const reference = (doc as { reference?: unknown })?.reference;
  if (typeof reference !== 'string') throw new Error(`${url.pathname}: "reference" must name the reference solution's .js file`);
  const exercise = parseExercise(doc, await (await fetchOk(new URL(reference, url))).text());
  for (const fixture of exercise.fixtures) {
    if (fixture.file) fixtureFiles.set(fixture.file, new Uint8Array(await (await fetchOk(new URL(fixture.file, url))).arrayBuffer()));
  }
  return exercise;
}

/** The bytes of the mesh files named by fixtures of exercises opened from links. */
export const fixtureFiles = new Map<string, Uint8Array>();

async function fetchOk(url: URL): Promise<Response> {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`could not fetch ${url.pathname} (${response.status})`);
  return response;
}
