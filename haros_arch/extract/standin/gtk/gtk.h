// Stand-in for GTK+ (gtk/gtk.h, every gtk/ header): the few GTK and GLib names ROS nodes
// use around an OpenCV window (image_view's nodelets under HAVE_GTK connect the window's
// "destroy" signal). No ROS call.
#ifndef HAROS_STANDIN_GTK_H
#define HAROS_STANDIN_GTK_H
typedef void* gpointer;
typedef int gboolean;
typedef struct _GtkWidget GtkWidget;
typedef struct _GtkWindow GtkWindow;
typedef void (*GCallback)(void);
#define GTK_WIDGET(object) ((GtkWidget*)(object))
#define GTK_WINDOW(object) ((GtkWindow*)(object))
#define G_CALLBACK(function) ((GCallback)(function))
unsigned long g_signal_connect(gpointer instance, const char* signal, GCallback handler,
                               gpointer data);
void gtk_init(int* argc, char*** argv);
void gtk_main();
void gtk_main_quit();
void gtk_widget_destroy(GtkWidget* widget);
#endif
