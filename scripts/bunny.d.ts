// The `bunny` package (the Stanford bunny, public domain) ships no types.
declare module 'bunny' {
  const bunny: { positions: number[][]; cells: number[][] };
  export default bunny;
}
