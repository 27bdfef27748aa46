(function(){
  var S = JSON.parse(document.getElementById('kanat-study').textContent), T = window.KANAT.template;
  function sel(id){return document.getElementById(id);}
  // plotly reads <b>, <a href> ... in text as markup: show user text (keys, values, names) as written
  function esc(v){return String(v).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');}
  function unit(n){return Object.prototype.hasOwnProperty.call(S.units, n) && S.units[n] ? ' [' + S.units[n] + ']' : '';}
  function fill(id, names, extra){var e = sel(id); if (!e) return;
    (extra || []).concat(names).forEach(function(n){var o = document.createElement('option'); o.value = n;
      o.textContent = n + unit(n); e.appendChild(o);});}
  fill('study-x', S.keys); fill('study-y', S.stats); fill('study-group', S.keys, ['(none)']);
  fill('map-z', S.stats); fill('map-x', S.keys); fill('map-y', S.keys);
  if (S.keys.length > 1){ sel('study-group').value = S.keys[1]; if (sel('map-y')) sel('map-y').value = S.keys[1]; }
  if (S.stats.indexOf(S.preferred) >= 0){
    sel('study-y').value = S.preferred; if (sel('map-z')) sel('map-z').value = S.preferred;}
  function col(n){return S.columns[n];}
  function ok(i){return S.columns.status[i] === 'ok';}
  function uniq(a){var seen = {}, out = []; a.forEach(function(v){var k = String(v);
    if (!(k in seen)){seen[k] = 1; out.push(v);}});
    return out.sort(function(p, q){return p < q ? -1 : p > q ? 1 : 0;});}
  function axis(n){return {title: {text: esc(n + unit(n))}};}
  function drawLines(){
    var x = sel('study-x').value, y = sel('study-y').value, g = sel('study-group').value, n = col('name').length;
    var groups = g === '(none)' ? [null] : uniq(col(g)), traces = [];
    groups.forEach(function(v){
      var idx = []; for (var i = 0; i < n; i++) if (ok(i) && (v === null || col(g)[i] === v)) idx.push(i);
      idx.sort(function(a, b){return col(x)[a] < col(x)[b] ? -1 : col(x)[a] > col(x)[b] ? 1 : 0;});
      traces.push({x: idx.map(function(i){return col(x)[i];}), y: idx.map(function(i){return col(y)[i];}),
        text: idx.map(function(i){return esc(col('name')[i]);}), mode: 'lines+markers', type: 'scatter',
        name: esc(v === null ? y : g + ' = ' + v)});
    });
    Plotly.react('plot-study', traces, {template: T, xaxis: axis(x), yaxis: axis(y), height: 440,
      title: {text: esc(y + ' against ' + x)}});
  }
  function drawMap(){
    if (!sel('map-z')) return;
    var z = sel('map-z').value, x = sel('map-x').value, y = sel('map-y').value, n = col('name').length;
    var xs = uniq(col(x)), ys = uniq(col(y)), sum = ys.map(function(){return xs.map(function(){return 0;});});
    var cnt = ys.map(function(){return xs.map(function(){return 0;});});
    for (var i = 0; i < n; i++) if (ok(i) && col(z)[i] !== null){
      var a = ys.indexOf(col(y)[i]), b = xs.indexOf(col(x)[i]); sum[a][b] += col(z)[i]; cnt[a][b] += 1;}
    var grid = sum.map(function(r, a){return r.map(function(v, b){return cnt[a][b] ? v / cnt[a][b] : null;});});
    Plotly.react('plot-map', [{type: 'heatmap', x: xs.map(esc), y: ys.map(esc), z: grid, colorscale: 'Viridis',
      colorbar: {title: {text: esc(z)}}, texttemplate: '%{z:.4~g}'}],
      {template: T, xaxis: axis(x), yaxis: axis(y), height: 440, title: {text: esc(z) + ' (mean over other parameters)'}});
  }
  ['study-x', 'study-y', 'study-group'].forEach(function(id){sel(id).addEventListener('change', drawLines);});
  ['map-z', 'map-x', 'map-y'].forEach(function(id){if (sel(id)) sel(id).addEventListener('change', drawMap);});
  drawLines(); drawMap();
  window.KANAT.study = {drawLines: drawLines, drawMap: drawMap};
})();
