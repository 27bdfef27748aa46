(function(){
  var figures = JSON.parse(document.getElementById('kanat-figures').textContent);
  var template = JSON.parse(document.getElementById('kanat-template').textContent);
  window.KANAT = {figures: figures, template: template, drawn: []};
  Object.keys(figures).forEach(function(id){
    var fig = figures[id]; fig.layout = fig.layout || {}; fig.layout.template = template;
    Plotly.newPlot(id, fig.data, fig.layout, {responsive: true, displaylogo: false});
    window.KANAT.drawn.push(id);
  });
})();
