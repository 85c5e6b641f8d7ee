// The mode-comparison page's script (docs/benchmarks.md): a click on a column
// heading of the table of runs sorts the runs by it, a second click reverses
// the order. The table itself is plain HTML; each cell's data-value holds its
// exact figure (cycles for the seconds shown), which the sort uses, and each
// heading's data-type says whether its column is numbers or text. The page's
// address may name a sort after '#': sort=KEY, or sort=-KEY for descending.
// The table records its order in data-sort-key, data-sort-order and
// data-order (the rows' positions in the page as written).
(function () {
  'use strict';

  const table = document.getElementById('runs-table');
  const heads = Array.from(table.tHead.rows[0].cells);
  const body = table.tBodies[0];
  const rows = Array.from(body.rows);
  rows.forEach((tr, i) => { tr.dataset.index = i; });

  const value = (tr, column) => {
    const td = tr.cells[column];
    return td.dataset.value !== undefined ? td.dataset.value : td.textContent;
  };

  function sortBy(column, descending) {
    const numeric = heads[column].dataset.type === 'number';
    const sorted = rows.slice().sort((a, b) => {
      const x = value(a, column), y = value(b, column);
      const order = numeric ? Number(x) - Number(y) : (x < y ? -1 : x > y ? 1 : 0);
      // Ties keep the page's order, whichever the direction.
      return (descending ? -order : order) || (a.dataset.index - b.dataset.index);
    });
    sorted.forEach((tr) => body.appendChild(tr));
    heads.forEach((th, k) => th.setAttribute('aria-sort', k === column ?
      (descending ? 'descending' : 'ascending') : 'none'));
    table.dataset.sortKey = heads[column].dataset.key;
    table.dataset.sortOrder = descending ? 'descending' : 'ascending';
    table.dataset.order = sorted.map((tr) => tr.dataset.index).join(' ');
  }

  heads.forEach((th, column) => {
    th.classList.add('sortable');
    th.title = 'Sort by this column';
    th.tabIndex = 0;
    const toggle = () => {
      const again = table.dataset.sortKey === th.dataset.key;
      sortBy(column, again ? table.dataset.sortOrder === 'ascending' : false);
    };
    th.addEventListener('click', toggle);
    th.addEventListener('keydown', (e) => {
      if (e.key === 'Enter' || e.key === ' ') {
        e.preventDefault();
        toggle();
      }
    });
  });

  const wanted = new URLSearchParams(location.hash.slice(1)).get('sort');
  if (wanted) {
    const column = heads.findIndex((th) => th.dataset.key === wanted.replace(/^-/, ''));
    if (column >= 0) sortBy(column, wanted.startsWith('-'));
  }
  table.dataset.rows = rows.length;
  document.documentElement.dataset.built = 'table';
})();
